//! [`RayHit`]: result of a ray cast.

use glam::Vec3;

use crate::body_handle::BodyHandle;
use crate::collider_handle::ColliderHandle;

/// A ray hit: which collider, where, and the surface normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayHit {
    /// Hit collider.
    pub collider: ColliderHandle,
    /// Its body.
    pub body: BodyHandle,
    /// Ray parameter: hit point = origin + toi · dir (metres when `dir` is unit length).
    pub toi: f32,
    /// World hit point.
    pub point: Vec3,
    /// World surface normal facing the ray (`-dir` when the ray starts inside).
    pub normal: Vec3,
}
