//! [`ModelSource`] and [`PartSource`]: a model file read and decoded on the CPU, ready to
//! upload. Reading needs no GPU, so it can run on any thread.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use glam::Mat4;

use super::gltf::{GltfFile, GltfFileLease};
use super::import_settings::ImportSettings;
use super::mesh_data::MeshData;
use super::model_load_error::ModelLoadError;
use crate::asset_io::AssetWarning;
use crate::model_material::{ImageSource, ModelMaterial};
use crate::texture::{decode_texture, TextureSource};

/// One mesh of a model with its material and its place in the model.
#[derive(Clone, Debug)]
pub struct PartSource {
    /// Object, group or node name from the file.
    pub name: String,
    /// The triangles.
    pub mesh: MeshData,
    /// The material the file gives it.
    pub material: ModelMaterial,
    /// The part's material could not be found because its library failed to load: it is
    /// drawn as the missing-texture placeholder.
    pub material_missing: bool,
    /// Part space → model space (a glTF node's world transform; identity for OBJ).
    pub transform: Mat4,
}

/// A model file read on the CPU: parts, the decoded images their materials use, and every
/// problem met. [`crate::Renderer::upload_model`] turns it into a drawable [`crate::Model`].
#[derive(Debug)]
pub struct ModelSource {
    /// The file.
    pub path: PathBuf,
    /// Parts, in file order.
    pub parts: Vec<PartSource>,
    /// Decoded images by source, each decoded once however many parts (and, for a glTF
    /// file, however many of its meshes) use it; `None` for one that failed (its error is in
    /// `problems`).
    pub images: HashMap<ImageSource, Option<Arc<TextureSource>>>,
    /// Problems that leave something to draw (missing MTL, failed texture), each once.
    pub problems: Vec<ModelLoadError>,
    /// Oddities worked around, each kind once.
    pub warnings: Vec<AssetWarning>,
    /// The glTF file the model was read from, whose images it decodes (shared with the
    /// file's other meshes).
    pub(crate) gltf: Option<Arc<GltfFile>>,
}

impl ModelSource {
    pub(crate) fn new(
        path: PathBuf,
        parts: Vec<PartSource>,
        problems: Vec<ModelLoadError>,
        warnings: Vec<AssetWarning>,
    ) -> Self {
        Self {
            path,
            parts,
            images: HashMap::new(),
            problems,
            warnings,
            gltf: None,
        }
    }

    /// Reads a model file (OBJ; glTF and GLB by extension) with its materials, and decodes
    /// the base-colour images it uses, downscaled to at most `max_texture_side` pixels.
    ///
    /// # Errors
    /// [`ModelLoadError`] naming the file when nothing can be drawn from it.
    pub fn load(
        path: &Path,
        settings: &ImportSettings,
        max_texture_side: u32,
    ) -> Result<Self, ModelLoadError> {
        Self::load_leased(path, settings, max_texture_side, None)
    }

    /// [`ModelSource::load`] of a model whose glTF file `lease` holds: the file is read
    /// and each of its images decoded once for every load holding the same file
    /// (`file.glb#mesh/N` for many `N`).
    ///
    /// # Errors
    /// As [`ModelSource::load`].
    pub fn load_leased(
        path: &Path,
        settings: &ImportSettings,
        max_texture_side: u32,
        lease: Option<&GltfFileLease>,
    ) -> Result<Self, ModelLoadError> {
        let mut source = super::load_model_source(path, settings, lease)?;
        source.decode_images(max_texture_side);
        for warning in &source.warnings {
            tracing::warn!("{warning}");
        }
        Ok(source)
    }

    /// Decodes every image a material slot names (base colour, metallic-roughness, normal,
    /// occlusion, emissive) not decoded yet; a failure becomes one problem naming the first
    /// material that uses the image.
    pub(crate) fn decode_images(&mut self, max_side: u32) {
        for part in &self.parts {
            let m = &part.material;
            let slots = [
                &m.base_color_texture,
                &m.metallic_roughness_texture,
                &m.normal_texture,
                &m.occlusion_texture,
                &m.emissive_texture,
            ];
            for slot in slots.into_iter().flatten() {
                if self.images.contains_key(&slot.image) {
                    continue;
                }
                let result = match &self.gltf {
                    Some(file) => file.decoded_image(&slot.image, max_side),
                    None => decode_texture(&slot.image, max_side).map(Arc::new),
                };
                let decoded = match result {
                    Ok(texture) => {
                        if let Some(warning) = &texture.warning {
                            self.warnings.push(warning.clone());
                        }
                        Some(texture)
                    }
                    Err(error) => {
                        self.problems.push(ModelLoadError::Texture {
                            obj: self.path.clone(),
                            material: part.material.name.clone(),
                            source: Box::new(error),
                        });
                        None
                    }
                };
                self.images.insert(slot.image.clone(), decoded);
            }
        }
    }

    /// Generates the tangents of every part that has a normal map and no tangents
    /// (MikkTSpace: the slow part of an upload, so a loader thread does it rather than the
    /// frame; without a normal map tangents are never read).
    pub fn generate_tangents(&mut self) {
        for part in &mut self.parts {
            if part.material.normal_texture.is_some() && !part.mesh.has_tangents() {
                part.mesh.generate_tangents();
            }
        }
    }

    /// Number of triangles of all parts.
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.parts.iter().map(|p| p.mesh.triangle_count()).sum()
    }
}
