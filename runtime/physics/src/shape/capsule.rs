//! [`Capsule`] shape.

use glam::Vec3;

/// Capsule along the local Y axis: the segment from `-half_height` to `+half_height`
/// swept by a sphere of `radius`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Capsule {
    /// Half length of the inner segment, metres (`>= 0`; zero is a sphere).
    pub half_height: f32,
    /// Radius, metres (`>= 0`).
    pub radius: f32,
}

impl Capsule {
    /// Segment end points in the local frame.
    #[must_use]
    pub fn segment(&self) -> (Vec3, Vec3) {
        (
            Vec3::new(0.0, -self.half_height, 0.0),
            Vec3::new(0.0, self.half_height, 0.0),
        )
    }
}
