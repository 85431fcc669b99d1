//! [`RayHit`]: where a ray met a collider.

use abi_stable::StableAbi;
use glam::Vec3;

use crate::Entity;

/// The first collider a ray hit ([`Ctx::raycast`](crate::Ctx::raycast)).
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct RayHit {
    /// The entity hit.
    pub entity: Entity,
    /// Where, world space.
    #[sabi(unsafe_opaque_field)]
    pub point: Vec3,
    /// Surface normal there.
    #[sabi(unsafe_opaque_field)]
    pub normal: Vec3,
    /// Distance along the ray, metres.
    pub distance: f32,
}
