//! Asset loading on [`Renderer`]: meshes, textures and model files, cached by path, with
//! visible fallbacks (the missing-texture placeholder, a placeholder cube) for files that
//! fail. Reading and decoding ([`ModelSource::load`]) need no GPU and may run on another
//! thread; [`Renderer::upload_model`] is the GPU half.

use std::path::Path;

use image::RgbaImage;

use super::Renderer;
use crate::builtin_meshes::BuiltinMeshes;
use crate::material::Material;
use crate::mesh::{
    cache_key, ImportSettings, InvalidMeshError, MeshData, MeshHandle, Model, ModelLoadError,
    ModelPart, ModelSource,
};
use crate::model_material::ImageSource;
use crate::shading_mode::ShadingMode;
use crate::texture::{decode_texture, TextureHandle, TextureLoadError, TextureSource};

impl Renderer {
    /// Handles of the built-in procedural meshes (cube, sphere, plane, capsule, cylinder).
    #[must_use]
    pub fn builtin_meshes(&self) -> &BuiltinMeshes {
        &self.builtin
    }

    /// Uploads a mesh.
    ///
    /// # Errors
    /// [`InvalidMeshError`] when `data` is not a valid triangle list.
    pub fn add_mesh(
        &mut self,
        data: &MeshData,
        label: &str,
    ) -> Result<MeshHandle, InvalidMeshError> {
        if !data.is_valid() {
            return Err(InvalidMeshError {
                label: label.to_owned(),
                vertices: data.vertices.len(),
                indices: data.indices.len(),
            });
        }
        let storage = &self.pipelines.layouts().mesh_storage;
        Ok(self.meshes.add(self.gpu.device(), storage, data, label))
    }

    /// Number of meshes uploaded so far (built-ins included).
    #[must_use]
    pub fn mesh_count(&self) -> usize {
        self.meshes.len()
    }

    /// GPU bytes of every mesh's buffers (vertices and indices) and of every texture's
    /// levels, uploaded so far.
    #[must_use]
    pub fn gpu_bytes(&self) -> (u64, u64) {
        (self.meshes.bytes(), self.textures.bytes())
    }

    /// The largest texture side this device takes, pixels: larger images are scaled down.
    #[must_use]
    pub fn max_texture_side(&self) -> u32 {
        self.gpu.device().limits().max_texture_dimension_2d
    }

    /// Uploads an sRGB image as a colour texture (base colour, emissive), with mipmaps.
    pub fn add_texture(&mut self, image: &RgbaImage, label: &str) -> TextureHandle {
        let source = TextureSource::from_image(image.clone(), true);
        self.textures.add(
            self.gpu.device(),
            self.gpu.queue(),
            &source.levels,
            label,
            false,
        )
    }

    /// Uploads an image as a data texture (normal, metallic-roughness, occlusion maps: the
    /// bytes are values, not sRGB colour), with mipmaps.
    pub fn add_data_texture(&mut self, image: &RgbaImage, label: &str) -> TextureHandle {
        let source = TextureSource::from_image(image.clone(), true);
        self.textures.add(
            self.gpu.device(),
            self.gpu.queue(),
            &source.levels,
            label,
            true,
        )
    }

    /// Loads a PNG or JPEG file as a texture with mipmaps (scaled down to fit the GPU, with
    /// a warning). A file is loaded once; later calls return the same handle.
    ///
    /// # Errors
    /// [`TextureLoadError`] naming the file when it cannot be read or decoded.
    pub fn load_texture(
        &mut self,
        path: impl AsRef<Path>,
    ) -> Result<TextureHandle, TextureLoadError> {
        self.load_texture_as(path, false)
    }

    /// Loads a PNG or JPEG file as a colour texture (`linear` false: sRGB; base colour,
    /// emissive) or a data texture (`linear` true: normal, metallic-roughness, occlusion).
    /// Loaded once per colour space.
    ///
    /// # Errors
    /// [`TextureLoadError`] naming the file when it cannot be read or decoded.
    pub fn load_texture_as(
        &mut self,
        path: impl AsRef<Path>,
        linear: bool,
    ) -> Result<TextureHandle, TextureLoadError> {
        let source = ImageSource::File(path.as_ref().to_owned());
        if let Some(handle) = self.textures.cached(&source, linear) {
            return Ok(handle);
        }
        let decoded = decode_texture(&source, self.max_texture_side())?;
        if let Some(warning) = &decoded.warning {
            tracing::warn!("{warning}");
        }
        Ok(self.upload_texture_as(&source, &decoded, linear))
    }

    /// Uploads a decoded colour (sRGB) texture for `source` (once per source).
    pub fn upload_texture(
        &mut self,
        source: &ImageSource,
        texture: &TextureSource,
    ) -> TextureHandle {
        self.upload_texture_as(source, texture, false)
    }

    /// Uploads a decoded texture for `source` as colour (sRGB) or data (`linear`), once per
    /// source and colour space.
    pub fn upload_texture_as(
        &mut self,
        source: &ImageSource,
        texture: &TextureSource,
        linear: bool,
    ) -> TextureHandle {
        self.textures
            .insert(self.gpu.device(), self.gpu.queue(), source, texture, linear)
    }

    /// Uploads `texture` in place of the texture `handle` names (its file changed on disk):
    /// every material drawn with the handle shows the new image from the next frame.
    pub fn replace_texture(
        &mut self,
        handle: TextureHandle,
        texture: &TextureSource,
        linear: bool,
    ) {
        self.textures
            .replace(self.gpu.device(), self.gpu.queue(), handle, texture, linear);
    }

    /// Frees the GPU buffers of a model's meshes (a model replaced by a reload; its handles
    /// draw nothing after) and forgets the images its materials were uploaded from, so the
    /// next upload of the same file takes its images anew. The textures themselves stay
    /// (other models may draw with them).
    pub fn release_model(&mut self, model: &Model) {
        let b = &self.builtin;
        let builtins = [b.cube, b.sphere, b.plane, b.capsule, b.cylinder];
        for part in &model.parts {
            if !builtins.contains(&part.mesh) {
                self.meshes.release(part.mesh);
            }
            let m = &part.file_material;
            for slot in [
                &m.base_color_texture,
                &m.metallic_roughness_texture,
                &m.normal_texture,
                &m.occlusion_texture,
                &m.emissive_texture,
            ]
            .into_iter()
            .flatten()
            {
                self.textures.forget(&slot.image);
            }
        }
    }

    /// Like [`Renderer::load_texture`], but a failure gives the magenta checker
    /// ([`Renderer::fallback_texture`]) along with the error, so drawing can go on. A file
    /// that failed before fails again without being read, and without an error (it was
    /// reported the first time).
    pub fn load_texture_or_fallback(
        &mut self,
        path: impl AsRef<Path>,
    ) -> (TextureHandle, Option<TextureLoadError>) {
        self.load_texture_or_fallback_as(path, false)
    }

    /// [`Renderer::load_texture_or_fallback`] as colour (sRGB) or data (`linear`).
    pub fn load_texture_or_fallback_as(
        &mut self,
        path: impl AsRef<Path>,
        linear: bool,
    ) -> (TextureHandle, Option<TextureLoadError>) {
        let source = ImageSource::File(path.as_ref().to_owned());
        if self.textures.has_failed(&source) {
            return (self.textures.checker(), None);
        }
        match self.load_texture_as(path, linear) {
            Ok(handle) => (handle, None),
            Err(error) => {
                self.textures.mark_failed(&source);
                tracing::warn!(%error, "texture replaced by the missing-texture placeholder");
                (self.textures.checker(), Some(error))
            }
        }
    }

    /// Width and height in pixels of a texture, `None` for a handle of another renderer.
    #[must_use]
    pub fn texture_size(&self, texture: TextureHandle) -> Option<(u32, u32)> {
        self.textures.get(texture).map(|t| t.size())
    }

    /// The magenta / dark checker standing for missing textures. Objects drawn with it show
    /// the missing-texture placeholder: a magenta checker in world space, whatever their
    /// colour and texture coordinates.
    #[must_use]
    pub fn fallback_texture(&self) -> TextureHandle {
        self.textures.checker()
    }

    /// A placeholder cube, shown in place of a model that failed to load.
    #[must_use]
    pub fn fallback_model(&self) -> Model {
        Model {
            parts: vec![ModelPart::new(
                "fallback",
                self.builtin.cube,
                Material::textured(self.textures.checker()),
            )],
        }
    }

    /// Loads a model file (OBJ with its MTL and textures) with default import settings: one
    /// [`ModelPart`] per material, triangulated, normals generated when missing,
    /// [`ShadingMode::Lit`]. A file that loaded without problems is cached: later calls
    /// return the same handles.
    ///
    /// # Errors
    /// [`ModelLoadError`] naming the file at fault (OBJ, MTL or texture). Use
    /// [`Renderer::load_model_or_fallback`] to get something drawable anyway.
    pub fn load_model(&mut self, path: impl AsRef<Path>) -> Result<Model, ModelLoadError> {
        let (model, problems) = self.load_model_parts(path.as_ref(), &ImportSettings::default())?;
        match problems.into_iter().next() {
            Some(first) => Err(first),
            None => Ok(model),
        }
    }

    /// Loads what it can of a model file and returns every problem met: a missing or broken
    /// texture becomes the placeholder, a missing MTL gives placeholder parts, an
    /// unreadable or malformed file gives [`Renderer::fallback_model`]. Problems are also
    /// logged.
    pub fn load_model_or_fallback(
        &mut self,
        path: impl AsRef<Path>,
    ) -> (Model, Vec<ModelLoadError>) {
        self.load_model_with(path.as_ref(), &ImportSettings::default())
    }

    /// [`Renderer::load_model_or_fallback`] with import settings (scale, up axis, normals).
    pub fn load_model_with(
        &mut self,
        path: &Path,
        settings: &ImportSettings,
    ) -> (Model, Vec<ModelLoadError>) {
        match self.load_model_parts(path, settings) {
            Ok(loaded) => loaded,
            Err(error) => {
                tracing::warn!(%error, "model replaced by the placeholder cube");
                (self.fallback_model(), vec![error])
            }
        }
    }

    /// Reads the model on this thread (or returns the cached one), then uploads it.
    fn load_model_parts(
        &mut self,
        path: &Path,
        settings: &ImportSettings,
    ) -> Result<(Model, Vec<ModelLoadError>), ModelLoadError> {
        let key = cache_key(path);
        if *settings == ImportSettings::default() {
            if let Some(model) = self.meshes.model(&key) {
                return Ok((model.clone(), Vec::new()));
            }
        }
        let source = ModelSource::load(path, settings, self.max_texture_side())?;
        let cache = *settings == ImportSettings::default();
        let (model, problems) = self.upload_model(source);
        if cache && problems.is_empty() {
            self.meshes.insert_model(key, model.clone());
        }
        Ok((model, problems))
    }

    /// Uploads a model read on the CPU: its meshes (tangents generated where a part has a
    /// normal map and the file gives none), its decoded images (each once per renderer and colour space) and its materials,
    /// drawn physically based with every map, alpha mode and sidedness the file gives. A part
    /// whose base colour texture or material library failed shows the missing-texture
    /// placeholder; a failed data map (normal, …) is left out. Returns the
    /// model and the source's problems, each logged once.
    pub fn upload_model(&mut self, source: ModelSource) -> (Model, Vec<ModelLoadError>) {
        let ModelSource {
            path,
            parts: sources,
            images,
            problems,
            ..
        } = source;
        for problem in &problems {
            tracing::warn!(error = %problem, "model loaded with a placeholder");
            if let ModelLoadError::Texture { source, .. } = problem {
                self.textures
                    .mark_failed(&ImageSource::File(source.path().to_owned()));
            }
        }
        let mut parts = Vec::with_capacity(sources.len());
        for mut part in sources {
            let label = format!("{}#{}", path.display(), part.name);
            // Tangents are read only with a normal map (the shader uses the geometric
            // normal without one): generated here when a loader thread has not.
            if part.material.normal_texture.is_some() && !part.mesh.has_tangents() {
                part.mesh.generate_tangents();
            }
            if !part.mesh.is_valid() {
                continue;
            }
            let storage = &self.pipelines.layouts().mesh_storage;
            let mesh = self
                .meshes
                .add_as_is(self.gpu.device(), storage, &part.mesh, &label);
            let mut file_material = part.material;
            let mut upload = |slot: &mut Option<crate::model_material::TextureRef>,
                              linear: bool| {
                let slot = slot.as_mut()?;
                let handle = match (
                    self.textures.cached(&slot.image, linear),
                    images.get(&slot.image),
                ) {
                    (Some(handle), _) => handle,
                    (None, Some(Some(decoded))) => {
                        self.upload_texture_as(&slot.image, decoded, linear)
                    }
                    _ => self.textures.checker(),
                };
                slot.handle = Some(handle);
                Some(handle)
            };
            let texture = upload(&mut file_material.base_color_texture, false);
            let metallic_roughness = upload(&mut file_material.metallic_roughness_texture, true);
            let normal = upload(&mut file_material.normal_texture, true);
            let occlusion = upload(&mut file_material.occlusion_texture, true);
            let emissive = upload(&mut file_material.emissive_texture, false);
            let checker = self.textures.checker();
            // A data map that failed draws as if absent (a checker normal map would be noise).
            let data = |h: Option<TextureHandle>| h.filter(|&h| h != checker);
            let material = if part.material_missing {
                Material::textured(self.textures.checker())
            } else {
                let m = &file_material;
                Material {
                    color: m.base_color,
                    texture,
                    shading: if m.unlit {
                        ShadingMode::Unlit
                    } else {
                        ShadingMode::Lit
                    },
                    metallic: m.metallic,
                    roughness: m.roughness,
                    metallic_roughness_texture: data(metallic_roughness),
                    normal_texture: data(normal),
                    normal_scale: m.normal_scale,
                    occlusion_texture: data(occlusion),
                    occlusion_strength: m.occlusion_strength,
                    emissive: m.emissive.map(|c| c * m.emissive_strength),
                    emissive_texture: data(emissive),
                    alpha_mode: m.alpha_mode,
                    double_sided: m.double_sided,
                }
            };
            parts.push(ModelPart {
                name: part.name,
                mesh,
                material,
                file_material,
                transform: part.transform,
            });
        }
        (Model { parts }, problems)
    }
}
