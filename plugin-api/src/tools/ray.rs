//! [`Ray`]: a half-line in world space.

use glam::Vec3;

/// A ray from `origin` along `direction` (unit length), world space, metres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Start point.
    pub origin: Vec3,
    /// Unit direction.
    pub direction: Vec3,
}

impl Ray {
    /// The point `distance` metres along the ray.
    pub fn at(&self, distance: f32) -> Vec3 {
        self.origin + self.direction * distance
    }
}
