//! [`Sphere`] shape.

/// Sphere centred at the collider origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// Radius in metres (`>= 0`; zero is a point).
    pub radius: f32,
}
