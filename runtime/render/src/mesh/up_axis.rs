//! [`UpAxis`]: which axis of a model file points up.

/// Which axis of a model file points up. Onyx is Y-up; Z-up files (CAD tools, 3ds Max,
/// Blender's raw coordinates) are turned on import so their +Z becomes +Y.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum UpAxis {
    /// +Y is up (OBJ and glTF convention): nothing changes.
    #[default]
    Y,
    /// +Z is up: rotated −90° about X, so (x, y, z) becomes (x, z, −y).
    Z,
}

impl UpAxis {
    /// A file-space vector in Onyx's Y-up space.
    #[must_use]
    pub fn to_y_up(self, [x, y, z]: [f32; 3]) -> [f32; 3] {
        match self {
            UpAxis::Y => [x, y, z],
            UpAxis::Z => [x, z, -y],
        }
    }
}
