//! Meshes: CPU data, procedural shapes, model files and the GPU-side cache.
//!
//! - `vertex`: [`Vertex`], the vertex format (position, normal, uv, tangent).
//! - `tangents`: MikkTSpace tangents for meshes that come without them.
//! - `mesh_data`: [`MeshData`], triangles on the CPU (normals generation, bounds).
//! - `procedural`: cube, sphere, plane, capsule, cylinder constructors on [`MeshData`].
//! - `mesh_handle`: [`MeshHandle`], names a mesh uploaded to a renderer.
//! - `model`: [`Model`] / [`ModelPart`], a loaded file on the GPU: one part per material.
//! - `model_source`: [`ModelSource`] / [`PartSource`], a model file read and decoded on the
//!   CPU (any thread), ready to upload.
//! - `model_loader`: the file's format by extension.
//! - `sub_asset`: [`SubAsset`], one piece of a model file named after a `#`
//!   (`file.glb#mesh/3`).
//! - `obj/`: OBJ + MTL, read tolerantly.
//! - `gltf/`: glTF 2.0 and GLB through the `gltf` crate.
//! - `import_settings`, `up_axis`, `normal_mode`: [`ImportSettings`] (scale, [`UpAxis`],
//!   [`NormalMode`]) a scene gives per model.
//! - `corner_normals`: generated normals (smoothing groups, crease angle).
//! - `model_load_error`: [`ModelLoadError`], why a model (or its MTL or texture) failed.
//! - `invalid_mesh_error`: [`InvalidMeshError`], why a [`MeshData`] cannot be uploaded.
//! - `gpu_mesh`: a mesh's GPU buffers and bounds.
//! - `mesh_cache`: every uploaded mesh, and loaded models by path.

mod corner_normals;
mod gltf;
mod gpu_mesh;
mod import_settings;
mod invalid_mesh_error;
mod mesh_cache;
mod mesh_data;
mod mesh_handle;
mod model;
mod model_load_error;
mod model_loader;
mod model_source;
mod normal_mode;
mod obj;
mod procedural;
mod sub_asset;
mod tangents;
mod up_axis;
mod vertex;

pub use gltf::catch_gltf_panics;
pub use gltf::load_gltf_buffers;
pub use gltf::{GltfFileLease, GltfFiles};
pub use import_settings::ImportSettings;
pub use invalid_mesh_error::InvalidMeshError;
pub(crate) use mesh_cache::{cache_key, MeshCache};
pub use mesh_data::MeshData;
pub use mesh_handle::MeshHandle;
pub use model::{Model, ModelPart};
pub use model_load_error::ModelLoadError;
pub use model_loader::is_gltf;
pub(crate) use model_loader::load_model_source;
pub use model_source::{ModelSource, PartSource};
pub use normal_mode::{NormalMode, DEFAULT_CREASE_DEGREES};
pub use sub_asset::SubAsset;
pub use up_axis::UpAxis;
pub use vertex::Vertex;

/// The geometry of a model file on the CPU, all parts merged into one triangle list in model
/// space (for collision shapes; no GPU needed, no image decoded). Materials are ignored.
///
/// # Errors
/// [`ModelLoadError`] naming the file when it cannot be read, is malformed or has no faces.
pub fn load_model_geometry(
    path: &std::path::Path,
    settings: &ImportSettings,
) -> Result<MeshData, ModelLoadError> {
    let model = load_model_source(path, settings, None)?;
    let mut merged = MeshData::default();
    for part in model.parts {
        let base = merged.vertices.len() as u32;
        let to_model = part.transform;
        merged
            .vertices
            .extend(part.mesh.vertices.into_iter().map(|mut v| {
                v.position = to_model
                    .transform_point3(glam::Vec3::from(v.position))
                    .to_array();
                v
            }));
        merged
            .indices
            .extend(part.mesh.indices.into_iter().map(|i| i + base));
    }
    Ok(merged)
}

/// [`load_model_geometry`] with default [`ImportSettings`] (kept for callers of the OBJ-only
/// version).
///
/// # Errors
/// As [`load_model_geometry`].
pub fn load_obj_geometry(path: &std::path::Path) -> Result<MeshData, ModelLoadError> {
    load_model_geometry(path, &ImportSettings::default())
}
