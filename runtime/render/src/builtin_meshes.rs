//! [`BuiltinMeshes`]: the procedural meshes every renderer uploads at start.

use crate::mesh::MeshHandle;

/// Segments around the round built-in shapes.
pub const BUILTIN_SEGMENTS: u32 = 32;
/// Rings pole to pole of the round built-in shapes.
pub const BUILTIN_RINGS: u32 = 16;

/// Handles of the procedural meshes uploaded by [`crate::Renderer::new`]: unit-sized,
/// centred on the origin.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BuiltinMeshes {
    /// Cube with 1 m edges.
    pub cube: MeshHandle,
    /// Sphere of radius 0.5 m.
    pub sphere: MeshHandle,
    /// 1 m square on XZ facing +Y.
    pub plane: MeshHandle,
    /// Capsule of radius 0.25 m, 1 m tall overall, along Y.
    pub capsule: MeshHandle,
    /// Cylinder of radius 0.5 m, 1 m tall, along Y.
    pub cylinder: MeshHandle,
}
