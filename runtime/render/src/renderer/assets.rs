//! Asset loading on [`Renderer`]: meshes, textures and OBJ models, cached by path, with
//! visible fallbacks (magenta checker, checker cube) for files that fail.

use std::path::Path;

use image::RgbaImage;

use super::Renderer;
use crate::builtin_meshes::BuiltinMeshes;
use crate::material::Material;
use crate::mesh::{
    cache_key, load_obj, InvalidMeshError, MeshData, MeshHandle, Model, ModelLoadError, ModelPart,
};
use crate::shading_mode::ShadingMode;
use crate::texture::{TextureHandle, TextureLoadError};

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
        Ok(self.meshes.add(self.gpu.device(), data, label))
    }

    /// Number of meshes uploaded so far (built-ins included).
    #[must_use]
    pub fn mesh_count(&self) -> usize {
        self.meshes.len()
    }

    /// Uploads an sRGB image as a texture, with mipmaps.
    pub fn add_texture(&mut self, image: &RgbaImage, label: &str) -> TextureHandle {
        let layout = &self.pipelines.layouts().material;
        self.textures.add(
            self.gpu.device(),
            self.gpu.queue(),
            layout,
            image,
            true,
            label,
        )
    }

    /// Loads a PNG or JPEG file as a texture with mipmaps. A file is loaded once; later calls
    /// return the same handle.
    ///
    /// # Errors
    /// [`TextureLoadError`] naming the file when it cannot be read, decoded or is too large.
    pub fn load_texture(
        &mut self,
        path: impl AsRef<Path>,
    ) -> Result<TextureHandle, TextureLoadError> {
        let layout = &self.pipelines.layouts().material;
        self.textures
            .load(self.gpu.device(), self.gpu.queue(), layout, path.as_ref())
    }

    /// Like [`Renderer::load_texture`], but a failure gives the magenta checker
    /// ([`Renderer::fallback_texture`]) along with the error, so drawing can go on.
    pub fn load_texture_or_fallback(
        &mut self,
        path: impl AsRef<Path>,
    ) -> (TextureHandle, Option<TextureLoadError>) {
        match self.load_texture(path) {
            Ok(handle) => (handle, None),
            Err(error) => {
                tracing::warn!(%error, "texture replaced by the fallback checker");
                (self.textures.checker(), Some(error))
            }
        }
    }

    /// Width and height in pixels of a texture, `None` for a handle of another renderer.
    #[must_use]
    pub fn texture_size(&self, texture: TextureHandle) -> Option<(u32, u32)> {
        self.textures.get(texture).map(|t| t.size())
    }

    /// The magenta / black checker shown in place of missing textures.
    #[must_use]
    pub fn fallback_texture(&self) -> TextureHandle {
        self.textures.checker()
    }

    /// A checker-textured cube, shown in place of a model that failed to load.
    #[must_use]
    pub fn fallback_model(&self) -> Model {
        Model {
            parts: vec![ModelPart {
                name: "fallback".to_owned(),
                mesh: self.builtin.cube,
                material: Material::textured(self.textures.checker()),
            }],
        }
    }

    /// Loads an OBJ file with its MTL and textures: one [`ModelPart`] per material,
    /// triangulated, normals generated when missing, [`ShadingMode::Lit`]. A file that
    /// loaded without problems is cached: later calls return the same handles.
    ///
    /// # Errors
    /// [`ModelLoadError`] naming the file at fault (OBJ, MTL or texture). Use
    /// [`Renderer::load_model_or_fallback`] to get something drawable anyway.
    pub fn load_model(&mut self, path: impl AsRef<Path>) -> Result<Model, ModelLoadError> {
        let (model, problems) = self.load_model_parts(path.as_ref())?;
        match problems.into_iter().next() {
            Some(first) => Err(first),
            None => Ok(model),
        }
    }

    /// Loads what it can of an OBJ file and returns every problem met: a missing or broken
    /// texture becomes the magenta checker, a missing MTL gives checker-textured parts, an
    /// unreadable or malformed OBJ gives [`Renderer::fallback_model`]. Problems are also
    /// logged.
    pub fn load_model_or_fallback(
        &mut self,
        path: impl AsRef<Path>,
    ) -> (Model, Vec<ModelLoadError>) {
        let (model, problems) = match self.load_model_parts(path.as_ref()) {
            Ok(loaded) => loaded,
            Err(error) => (self.fallback_model(), vec![error]),
        };
        for problem in &problems {
            tracing::warn!(error = %problem, "model loaded with a fallback");
        }
        (model, problems)
    }

    /// Loads the model, turning non-fatal problems into fallbacks listed beside it.
    fn load_model_parts(
        &mut self,
        path: &Path,
    ) -> Result<(Model, Vec<ModelLoadError>), ModelLoadError> {
        let key = cache_key(path);
        if let Some(model) = self.meshes.model(&key) {
            return Ok((model.clone(), Vec::new()));
        }
        let obj = load_obj(path)?;
        let mut problems = obj.problems;
        let mtl_failed = problems
            .iter()
            .any(|p| matches!(p, ModelLoadError::Mtl { .. }));
        let mut parts = Vec::with_capacity(obj.parts.len());
        for part in obj.parts {
            let label = format!("{}#{}", path.display(), part.name);
            let mesh = self.meshes.add(self.gpu.device(), &part.mesh, &label);
            let material = match part.material {
                Some(obj_material) => {
                    let texture = obj_material.texture.as_ref().map(|texture_path| {
                        match self.load_texture(texture_path) {
                            Ok(handle) => handle,
                            Err(source) => {
                                problems.push(ModelLoadError::Texture {
                                    obj: path.to_owned(),
                                    material: obj_material.name.clone(),
                                    source: Box::new(source),
                                });
                                self.textures.checker()
                            }
                        }
                    });
                    let [r, g, b] = obj_material.diffuse;
                    Material {
                        color: [r, g, b, 1.0],
                        texture,
                        shading: ShadingMode::Lit,
                    }
                }
                None if mtl_failed => Material::textured(self.textures.checker()),
                None => Material::default(),
            };
            parts.push(ModelPart {
                name: part.name,
                mesh,
                material,
            });
        }
        let model = Model { parts };
        if problems.is_empty() {
            self.meshes.insert_model(key, model.clone());
        }
        Ok((model, problems))
    }
}
