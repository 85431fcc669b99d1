//! Where over a step two convex shapes, one translating past the other without touching,
//! come closest ([`closest_miss`]): the configuration a fast pair's speculative contact is
//! made in when the two go by each other.
//!
//! A speculative contact holds its bodies apart along one normal for the whole step, as if
//! they moved along straight lines against a plane. Made from the closest points at the
//! step's start, for a body that goes by the other that plane stands across its path (a
//! bullet 1 cm beside another, metres behind it, met it along a normal nearly along their
//! paths, and threw both at 30 m/s). Made where they come closest, its normal is square to
//! their relative path, its separation the least over the step, and it holds only what else
//! would push them together.

use glam::Vec3;

use super::gjk::{gjk_distance, GjkStatus};
use crate::pose::Pose;
use crate::shape::Shape;

/// Halvings of the step in the search for the closest approach. Bounded `[8, 24]`: fewer
/// leave the normal of a near miss more tilted towards the path (harmless, the separation is
/// the least distance, but the contact holds less sideways), more cost GJK runs on every fast
/// pair that comes near another.
const CLOSEST_APPROACH_HALVINGS: u32 = 14;

/// The fraction of the step at which convex shapes `a` at `pa` and `b` at `pb` (at the
/// step's start) come closest as `b` moves by `closing` relative to `a`, where they never
/// touch over the step and are closing at its start; `None` where they touch (a hit, whose
/// contact is made at the step's start as for any pair) or are not closing, or a shape is not
/// convex.
///
/// Shapes translating against each other have a distance convex in time, so the search
/// halves on the sign of its slope (`closing · n` along the closest points' normal) and on
/// overlap. The time returned is on the receding side of the closest approach (the distance
/// no longer falls there), and the distance there is the least over the step, to within the
/// halvings.
#[must_use]
pub(crate) fn closest_miss(
    a: &Shape,
    pa: &Pose,
    b: &Shape,
    pb: &Pose,
    closing: Vec3,
) -> Option<f32> {
    let (core_a, radius_a) = a.convex_core()?;
    let (core_b, radius_b) = b.convex_core()?;
    // The shapes with B moved by `t` of the step: `None` where they overlap, else the normal
    // from A to B at their closest points (the distance falls while `closing · n < 0`).
    let normal_at = |t: f32| {
        let moved = Pose::new(pb.translation + closing * t, pb.rotation);
        let g = gjk_distance(&core_a, pa, &core_b, &moved);
        (g.status != GjkStatus::Overlapping && g.distance > radius_a + radius_b).then_some(g.normal)
    };
    let falls = |n: Vec3| n.dot(closing) < 0.0;
    let mut n_lo = normal_at(0.0).filter(|&n| falls(n))?;
    let mut n_hi = normal_at(1.0);
    if n_hi.is_some_and(falls) {
        return Some(1.0);
    }
    // Invariant: at `lo` apart and closing; at `hi` touching (`None`), or apart and receding.
    let (mut lo, mut hi) = (0.0f32, 1.0f32);
    for _ in 0..CLOSEST_APPROACH_HALVINGS {
        let mid = 0.5 * (lo + hi);
        match normal_at(mid) {
            Some(n) if falls(n) => (lo, n_lo) = (mid, n),
            n => (hi, n_hi) = (mid, n),
        }
    }
    // Past a closest approach the normal has barely turned; past a body gone through the
    // other between two tries (thinner than a try's motion), it has turned over: a hit.
    n_hi.filter(|n| n.dot(n_lo) > 0.0).map(|_| hi)
}
