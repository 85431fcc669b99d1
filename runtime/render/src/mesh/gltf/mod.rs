//! glTF 2.0 (`.gltf` with external or embedded buffers, `.glb`) through the `gltf` crate.
//!
//! - `gltf_loader`: the file into a [`crate::ModelSource`]: the default scene's nodes
//!   walked, one part per primitive at its node's world transform (the entry point).
//! - `gltf_buffers`: buffer and image bytes (GLB chunk, `data:` URIs, files beside the
//!   model — regular files only).
//! - `gltf_primitive`: a primitive's accessors (sparse ones included) into a [`crate::MeshData`].
//! - `gltf_material`: a material into a [`crate::ModelMaterial`] (metallic-roughness,
//!   samplers, `KHR_texture_transform`, `KHR_materials_emissive_strength`).
//! - `crate_panics`: the guard every read through the `gltf` crate runs behind (the crate
//!   panics on some malformed files).

mod crate_panics;
mod gltf_buffers;
mod gltf_loader;
mod gltf_material;
mod gltf_primitive;

pub use crate_panics::catch_gltf_panics;

use std::path::Path;

use crate::mesh::import_settings::ImportSettings;
use crate::mesh::model_load_error::ModelLoadError;
use crate::mesh::model_source::ModelSource;

/// [`gltf_loader::load_gltf_source`] behind [`catch_gltf_panics`].
pub(crate) fn load_gltf_source(
    path: &Path,
    settings: &ImportSettings,
) -> Result<ModelSource, ModelLoadError> {
    catch_gltf_panics(path, || gltf_loader::load_gltf_source(path, settings))
}
