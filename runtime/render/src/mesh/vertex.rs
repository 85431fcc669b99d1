//! [`Vertex`]: the vertex format of every mesh.

/// One mesh vertex: position (m), unit normal and texture coordinate (0..1, origin top-left).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    /// Position in model space, metres.
    pub position: [f32; 3],
    /// Unit normal in model space.
    pub normal: [f32; 3],
    /// Texture coordinate; (0, 0) is the top-left of the image.
    pub uv: [f32; 2],
}

impl Vertex {
    /// A vertex from its parts.
    #[must_use]
    pub const fn new(position: [f32; 3], normal: [f32; 3], uv: [f32; 2]) -> Self {
        Self {
            position,
            normal,
            uv,
        }
    }
}
