//! [`RenderAssets`]: the GPU copies of the registered models and textures, loaded off the
//! frame thread: a frame asks for what it draws, draws what is ready (a model still loading
//! is not drawn, a texture still loading shows the missing-texture checker) and uploads what
//! the loader threads have finished.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use onyx_plugin_api::{Event, GraphicsEvent, MeshId, TextureId};
use onyx_render::mesh::{Model, ModelPart};
use onyx_render::model_material::ImageSource;
use onyx_render::{AssetLoader, Loaded, Renderer, TextureHandle};

use crate::assets::AssetRegistry;

/// What a load was asked for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum AssetKey {
    /// A registered model.
    Mesh(MeshId),
    /// A registered texture (sRGB colour).
    Texture(TextureId),
}

/// Models and textures on the GPU by id, and the loads in flight.
#[derive(Debug)]
pub(crate) struct RenderAssets {
    models: HashMap<MeshId, Model>,
    textures: HashMap<TextureId, TextureHandle>,
    loader: AssetLoader<AssetKey>,
    /// Loads asked for and not uploaded yet, with the file each reads.
    loading: HashMap<AssetKey, PathBuf>,
    /// Bumped whenever an asset is first put on the GPU (the files to watch changed).
    generation: u64,
}

fn asset_failed(path: &Path, message: String) -> Event {
    Event::Graphics(GraphicsEvent::AssetFailed {
        path: path.display().to_string(),
        message,
    })
}

impl RenderAssets {
    pub(crate) fn new(renderer: &Renderer) -> Self {
        Self {
            models: HashMap::new(),
            textures: HashMap::new(),
            loader: AssetLoader::new(renderer.max_texture_side()),
            loading: HashMap::new(),
            generation: 0,
        }
    }

    /// Loads in flight.
    pub(crate) fn pending(&self) -> usize {
        self.loading.len()
    }

    /// Changes whenever a model or texture is first put on the GPU.
    pub(crate) fn generation(&self) -> u64 {
        self.generation
    }

    /// The model of `id` if it is on the GPU; a built-in shape is at once, a registered
    /// file is asked for (once) and is `None` until its load is uploaded. `None` too for
    /// an unknown id.
    pub(crate) fn model(
        &mut self,
        id: MeshId,
        renderer: &Renderer,
        assets: &AssetRegistry,
    ) -> Option<&Model> {
        if !self.models.contains_key(&id) {
            let builtin = renderer.builtin_meshes();
            let mesh = match id {
                MeshId::CUBE => builtin.cube,
                MeshId::SPHERE => builtin.sphere,
                MeshId::PLANE => builtin.plane,
                MeshId::CAPSULE => builtin.capsule,
                MeshId::CYLINDER => builtin.cylinder,
                _ => {
                    let path = assets.mesh_path(id)?;
                    self.request_model(id, path, assets);
                    return None;
                }
            };
            let part = ModelPart::new("builtin", mesh, onyx_render::Material::color(1.0, 1.0, 1.0));
            self.models.insert(id, Model { parts: vec![part] });
            self.generation += 1;
        }
        self.models.get(&id)
    }

    /// The texture of `id`: `None` for no texture (or an unknown id), the checker while it
    /// loads (asked for once).
    pub(crate) fn texture(
        &mut self,
        id: TextureId,
        renderer: &Renderer,
        assets: &AssetRegistry,
    ) -> Option<TextureHandle> {
        if id == TextureId::NONE {
            return None;
        }
        if let Some(handle) = self.textures.get(&id) {
            return Some(*handle);
        }
        let key = AssetKey::Texture(id);
        if !self.loading.contains_key(&key) {
            let path = assets.resolve(assets.texture_path(id)?);
            self.loader.request_texture(key, &path, false);
            self.loading.insert(key, path);
        }
        Some(renderer.fallback_texture())
    }

    fn request_model(&mut self, id: MeshId, path: &Path, assets: &AssetRegistry) {
        let key = AssetKey::Mesh(id);
        if self.loading.contains_key(&key) {
            return;
        }
        let settings = assets.import_settings(path);
        let path = assets.resolve(path);
        self.loader.request_model(key, &path, settings);
        self.loading.insert(key, path);
    }

    /// Uploads every load the threads have finished; failures become `events`.
    pub(crate) fn upload_finished(&mut self, renderer: &mut Renderer, events: &mut Vec<Event>) {
        while let Some(loaded) = self.loader.poll() {
            self.upload(loaded, renderer, events);
        }
    }

    /// Waits until every load asked for is uploaded, at most `timeout`; `false` when some
    /// were still loading then (they stay placeholders, and a warning names them).
    pub(crate) fn finish_loading(
        &mut self,
        renderer: &mut Renderer,
        events: &mut Vec<Event>,
        timeout: Duration,
    ) -> bool {
        let deadline = Instant::now() + timeout;
        while !self.loading.is_empty() {
            match self.loader.wait_until(deadline) {
                Some(loaded) => self.upload(loaded, renderer, events),
                None => break,
            }
        }
        if self.loading.is_empty() {
            return true;
        }
        let mut files: Vec<String> = self
            .loading
            .values()
            .map(|p| format!("`{}`", p.display()))
            .collect();
        files.sort();
        tracing::warn!(
            "assets still loading after {:.0} s are drawn as placeholders: {}",
            timeout.as_secs_f64(),
            files.join(", ")
        );
        false
    }

    /// Loads the model or texture of `key` again (its file changed on disk): what is on
    /// the GPU is kept until the new load is uploaded, and kept for good if it fails.
    pub(crate) fn reload(&mut self, key: AssetKey, assets: &AssetRegistry) {
        match key {
            AssetKey::Mesh(id) if self.models.contains_key(&id) => {
                if let Some(path) = assets.mesh_path(id) {
                    self.request_model(id, path, assets);
                }
            }
            AssetKey::Texture(id) if self.textures.contains_key(&id) => {
                if self.loading.contains_key(&key) {
                    return;
                }
                if let Some(path) = assets.texture_path(id) {
                    let path = assets.resolve(path);
                    self.loader.request_texture(key, &path, false);
                    self.loading.insert(key, path);
                }
            }
            _ => {}
        }
    }

    /// Every model and texture on the GPU or loading, with the file it was read from.
    pub(crate) fn files(&self, assets: &AssetRegistry) -> Vec<(AssetKey, PathBuf)> {
        let models = self
            .models
            .keys()
            .filter_map(|&id| Some((AssetKey::Mesh(id), assets.resolve(assets.mesh_path(id)?))));
        let textures = self.textures.keys().filter_map(|&id| {
            Some((
                AssetKey::Texture(id),
                assets.resolve(assets.texture_path(id)?),
            ))
        });
        models.chain(textures).collect()
    }

    fn upload(
        &mut self,
        loaded: Loaded<AssetKey>,
        renderer: &mut Renderer,
        events: &mut Vec<Event>,
    ) {
        let key = *loaded.key();
        self.loading.remove(&key);
        let reloading = match key {
            AssetKey::Mesh(id) => self.models.contains_key(&id),
            AssetKey::Texture(id) => self.textures.contains_key(&id),
        };
        if !reloading {
            self.generation += 1;
        }
        let failed = |path: &Path, message: String, events: &mut Vec<Event>| {
            let message = if reloading {
                format!("{message}; the last good version is kept")
            } else {
                message
            };
            events.push(asset_failed(path, message));
        };
        match loaded {
            Loaded::Model {
                key: _,
                path,
                result,
            } => {
                let AssetKey::Mesh(id) = key else { return };
                match result {
                    Ok(source) => {
                        // The old meshes go, and its images are taken anew from the file.
                        if let Some(old) = self.models.get(&id) {
                            renderer.release_model(old);
                            tracing::info!(path = %path.display(), "model reloaded");
                        }
                        let (model, problems) = renderer.upload_model(source);
                        for problem in problems {
                            failed(&path, problem.to_string(), events);
                        }
                        self.models.insert(id, model);
                    }
                    Err(error) => {
                        tracing::warn!(%error, "model not drawn (kept or replaced by the placeholder cube)");
                        failed(&path, error.to_string(), events);
                        self.models
                            .entry(id)
                            .or_insert_with(|| renderer.fallback_model());
                    }
                }
            }
            Loaded::Texture {
                key: _,
                path,
                linear,
                result,
            } => {
                let AssetKey::Texture(id) = key else { return };
                let source = ImageSource::File(path.clone());
                match result {
                    Ok(texture) => {
                        if let Some(warning) = &texture.warning {
                            tracing::warn!("{warning}");
                        }
                        match self.textures.get(&id) {
                            Some(&old) if old != renderer.fallback_texture() => {
                                renderer.replace_texture(old, &texture, linear);
                                tracing::info!(path = %path.display(), "texture reloaded");
                            }
                            _ => {
                                let handle = renderer.upload_texture_as(&source, &texture, linear);
                                self.textures.insert(id, handle);
                            }
                        }
                    }
                    Err(error) => {
                        tracing::warn!(%error, "texture not shown (kept or replaced by the missing-texture placeholder)");
                        failed(&path, error.to_string(), events);
                        self.textures
                            .entry(id)
                            .or_insert_with(|| renderer.fallback_texture());
                    }
                }
            }
            Loaded::Panicked { path, message, .. } => {
                failed(
                    &path,
                    format!(
                        "`{}` could not be loaded (the decoder failed: {message})",
                        path.display()
                    ),
                    events,
                );
                match key {
                    AssetKey::Mesh(id) => {
                        self.models
                            .entry(id)
                            .or_insert_with(|| renderer.fallback_model());
                    }
                    AssetKey::Texture(id) => {
                        self.textures
                            .entry(id)
                            .or_insert_with(|| renderer.fallback_texture());
                    }
                }
            }
        }
    }
}
