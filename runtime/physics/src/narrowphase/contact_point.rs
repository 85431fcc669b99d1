//! [`ContactPoint`]: one persistent contact point with its accumulated impulses.

use glam::Vec3;

/// One contact point, stored in body-local coordinates so it survives far-from-origin
/// motion and can be matched frame to frame for warm starting.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct ContactPoint {
    /// Point in body A's frame (relative to its origin), metres.
    pub local_a: Vec3,
    /// Point in body B's frame, metres.
    pub local_b: Vec3,
    /// Signed separation along the normal at the start of the last step (negative =
    /// penetration), metres.
    pub separation: f32,
    /// Separation when the point was generated (its two local points then coincided).
    pub(crate) generated_separation: f32,
    /// Accumulated normal impulse of the last step, N·s (warm start).
    pub normal_impulse: f32,
    /// This point's share (in proportion to its normal impulse) of its manifold's friction
    /// impulse of the last step, as a world vector, N·s (warm start; a vector so that it
    /// survives changes of the tangent basis).
    pub tangent_impulse: Vec3,
    /// This point's share of its manifold's twist friction impulse (about the normal) of the
    /// last step, N·m·s (warm start).
    pub(crate) twist_impulse: f32,
    /// Largest normal impulse applied in one substep during the last step, N·s.
    pub max_normal_impulse: f32,
    /// Restitution bounced or held the point in the last step: its impulse was an impact's,
    /// not a load's (not warm started).
    pub(crate) impact: bool,
    /// Feature id (for matching), `u32::MAX` when unknown.
    pub id: u32,
    /// Offset from A's centre of mass, world axes, at generation (solver use).
    pub(crate) anchor_a: Vec3,
    /// Offset from B's centre of mass, world axes, at generation.
    pub(crate) anchor_b: Vec3,
}
