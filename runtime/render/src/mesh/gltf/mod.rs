//! glTF 2.0 (`.gltf` with external or embedded buffers, `.glb`) through the `gltf` crate.
//!
//! - `gltf_loader`: the file into a [`crate::ModelSource`]: the default scene's nodes
//!   walked, one part per primitive at its node's world transform (the entry point).
//! - `gltf_mesh_loader`: one mesh of the file (`file.glb#mesh/N`) into a
//!   [`crate::ModelSource`], in the mesh's own space (a scene entity draws each mesh).
//! - `gltf_file`: [`GltfFile`], a file read once (document, buffers, decoded images) and
//!   shared by the loads of its meshes through [`GltfFiles`] leases.
//! - `gltf_buffers`: buffer and image bytes (GLB chunk, `data:` URIs, files beside the
//!   model — regular files only).
//! - `gltf_primitive`: a primitive's accessors (sparse ones included) into a [`crate::MeshData`].
//! - `gltf_material`: a material into a [`crate::ModelMaterial`] (metallic-roughness,
//!   samplers, `KHR_texture_transform`, `KHR_materials_emissive_strength`).
//! - `crate_panics`: the guard every read through the `gltf` crate runs behind (the crate
//!   panics on some malformed files).

mod crate_panics;
mod gltf_buffers;
mod gltf_file;
mod gltf_loader;
mod gltf_material;
mod gltf_mesh_loader;
mod gltf_primitive;

pub use crate_panics::catch_gltf_panics;
pub use gltf_buffers::load_buffers as load_gltf_buffers;
pub(crate) use gltf_file::GltfFile;
pub use gltf_file::{GltfFileLease, GltfFiles};

use std::path::Path;
use std::sync::Arc;

use crate::mesh::import_settings::ImportSettings;
use crate::mesh::model_load_error::ModelLoadError;
use crate::mesh::model_source::ModelSource;

/// The file at `path` as `lease` holds it (read once for every load holding it), or read
/// now for this load alone.
fn file(path: &Path, lease: Option<&GltfFileLease>) -> Result<Arc<GltfFile>, ModelLoadError> {
    match lease {
        Some(lease) if lease.path() == path => lease.file(),
        _ => Ok(Arc::new(catch_gltf_panics(path, || GltfFile::read(path))?)),
    }
}

/// [`gltf_loader::load_gltf_source`] behind [`catch_gltf_panics`].
pub(crate) fn load_gltf_source(
    path: &Path,
    settings: &ImportSettings,
    lease: Option<&GltfFileLease>,
) -> Result<ModelSource, ModelLoadError> {
    let file = file(path, lease)?;
    catch_gltf_panics(path, || gltf_loader::load_gltf_source(&file, settings))
}

/// [`gltf_mesh_loader::load_gltf_mesh_source`] behind [`catch_gltf_panics`].
pub(crate) fn load_gltf_mesh_source(
    path: &Path,
    mesh_index: usize,
    settings: &ImportSettings,
    lease: Option<&GltfFileLease>,
) -> Result<ModelSource, ModelLoadError> {
    let file = file(path, lease)?;
    catch_gltf_panics(path, || {
        gltf_mesh_loader::load_gltf_mesh_source(&file, mesh_index, settings)
    })
}
