//! [`HalfSpace`] shape (infinite plane).

use glam::Vec3;

/// Solid half space below a plane through the collider origin: points with
/// `dot(normal, p) <= 0` are inside. Use for ground planes on fixed bodies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HalfSpace {
    /// Outward unit normal in the local frame.
    pub normal: Vec3,
}
