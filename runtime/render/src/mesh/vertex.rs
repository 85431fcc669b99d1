//! [`Vertex`]: the vertex format of every mesh.

/// One mesh vertex: position (m), unit normal, texture coordinate (0..1, origin top-left) and
/// tangent (for normal maps).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    /// Position in model space, metres.
    pub position: [f32; 3],
    /// Unit normal in model space.
    pub normal: [f32; 3],
    /// Texture coordinate; (0, 0) is the top-left of the image.
    pub uv: [f32; 2],
    /// Unit tangent (xyz, along +u) and handedness (w = ±1: the bitangent is
    /// `w · normal × tangent`), MikkTSpace as glTF defines it. `w == 0` means "not computed":
    /// [`crate::Renderer::add_mesh`] generates the tangents of such a mesh
    /// ([`crate::MeshData::generate_tangents`]).
    pub tangent: [f32; 4],
}

impl Vertex {
    /// A vertex from its parts; the tangent is left to be generated.
    #[must_use]
    pub const fn new(position: [f32; 3], normal: [f32; 3], uv: [f32; 2]) -> Self {
        Self {
            position,
            normal,
            uv,
            tangent: [0.0; 4],
        }
    }

    /// Sets the tangent (xyz unit, w = ±1 handedness).
    #[must_use]
    pub const fn with_tangent(mut self, tangent: [f32; 4]) -> Self {
        self.tangent = tangent;
        self
    }
}
