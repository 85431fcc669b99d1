//! [`InvalidMeshError`]: why [`crate::MeshData`] cannot be uploaded.

/// Why [`crate::Renderer::add_mesh`] refused a mesh.
#[derive(Debug, thiserror::Error)]
#[error(
    "mesh `{label}` is not a valid triangle list ({vertices} vertices, {indices} indices): it needs \
     at least one triangle, a multiple of 3 indices, and every index below the vertex count"
)]
pub struct InvalidMeshError {
    /// Label given to the mesh.
    pub label: String,
    /// Vertex count.
    pub vertices: usize,
    /// Index count.
    pub indices: usize,
}
