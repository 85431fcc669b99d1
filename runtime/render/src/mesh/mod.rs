//! Meshes: CPU data, procedural shapes, OBJ loading and the GPU-side cache.
//!
//! - `vertex`: [`Vertex`], the vertex format (position, normal, uv).
//! - `mesh_data`: [`MeshData`], triangles on the CPU (normals generation, bounds).
//! - `procedural`: cube, sphere, plane, capsule, cylinder constructors on [`MeshData`].
//! - `mesh_handle`: [`MeshHandle`], names a mesh uploaded to a renderer.
//! - `model`: [`Model`] / [`ModelPart`], a loaded file: one part per material.
//! - `model_load_error`: [`ModelLoadError`], why an OBJ/MTL (or its texture) failed.
//! - `obj_loader`: reads OBJ + MTL through `tobj` into parts.
//! - `invalid_mesh_error`: [`InvalidMeshError`], why a [`MeshData`] cannot be uploaded.
//! - `gpu_mesh`: a mesh's GPU buffers and bounds.
//! - `mesh_cache`: every uploaded mesh, and loaded models by path.

mod gpu_mesh;
mod invalid_mesh_error;
mod mesh_cache;
mod mesh_data;
mod mesh_handle;
mod model;
mod model_load_error;
mod obj_loader;
mod procedural;
mod vertex;

pub use invalid_mesh_error::InvalidMeshError;
pub(crate) use mesh_cache::{cache_key, MeshCache};
pub use mesh_data::MeshData;
pub use mesh_handle::MeshHandle;
pub use model::{Model, ModelPart};
pub use model_load_error::ModelLoadError;
pub(crate) use obj_loader::load_obj;
pub use obj_loader::load_obj_geometry;
pub use vertex::Vertex;
