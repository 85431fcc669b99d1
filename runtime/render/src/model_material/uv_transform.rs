//! [`UvTransform`]: offset, rotation and scale of texture coordinates.

/// Texture-coordinate transform, applied as glTF's `KHR_texture_transform` defines it:
/// scale, then rotate (radians, counter-clockwise in UV space), then offset. OBJ's `-s` and
/// `-o` map options are a scale and an offset.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UvTransform {
    /// Added last.
    pub offset: [f32; 2],
    /// Rotation, radians.
    pub rotation: f32,
    /// Multiplied first.
    pub scale: [f32; 2],
}

impl Default for UvTransform {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl UvTransform {
    /// Leaves coordinates as they are.
    pub const IDENTITY: Self = Self {
        offset: [0.0, 0.0],
        rotation: 0.0,
        scale: [1.0, 1.0],
    };

    /// Whether it changes nothing.
    #[must_use]
    pub fn is_identity(&self) -> bool {
        *self == Self::IDENTITY
    }

    /// The transformed coordinate (top-left origin, as glTF and the renderer use).
    #[must_use]
    pub fn apply(&self, [u, v]: [f32; 2]) -> [f32; 2] {
        let (su, sv) = (u * self.scale[0], v * self.scale[1]);
        let (sin, cos) = self.rotation.sin_cos();
        [
            cos * su + sin * sv + self.offset[0],
            -sin * su + cos * sv + self.offset[1],
        ]
    }
}
