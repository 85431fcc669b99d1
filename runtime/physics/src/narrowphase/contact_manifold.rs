//! [`ContactManifold`]: up to four contact points sharing a normal.

use arrayvec::ArrayVec;
use glam::Vec3;

use super::contact_point::ContactPoint;
use super::raw_manifold::MAX_MANIFOLD_POINTS;

/// Contact points of one feature pair with a shared normal (from A to B).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct ContactManifold {
    /// Unit normal from collider A to collider B, world axes, as generated: it stays fixed
    /// while the pair's manifolds are reused (see `narrowphase::narrow_phase`).
    pub normal: Vec3,
    /// Points, stored inline: the solver reads every manifold's points each step, and a
    /// separate allocation per manifold cost a cache miss each time.
    pub points: ArrayVec<ContactPoint, MAX_MANIFOLD_POINTS>,
    /// First friction direction (world), fixed for the step.
    pub(crate) tangent1: Vec3,
    /// A frictionless face's held normal (zero while none), which a one-point manifold in
    /// between does not replace (see `narrow_phase::FRICTIONLESS_NORMAL_HOLD_ANGLE`).
    pub(crate) face_normal: Vec3,
}

impl ContactManifold {
    /// Smallest separation among the points (metres), `f32::MAX` if none.
    #[must_use]
    pub fn min_separation(&self) -> f32 {
        self.points
            .iter()
            .map(|p| p.separation)
            .fold(f32::MAX, f32::min)
    }

    /// Sum of the points' accumulated normal impulses of the last step, N·s.
    #[must_use]
    pub fn total_normal_impulse(&self) -> f32 {
        self.points.iter().map(|p| p.normal_impulse).sum()
    }
}
