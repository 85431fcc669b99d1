//! Where over a step two convex shapes, one translating past the other without touching,
//! come closest ([`closest_miss`]): where the speculative contact of a pair that goes by is
//! made (and, for a mesh's triangle, that it has none).
//!
//! A speculative contact holds its bodies apart along one normal for the whole step, as if
//! they moved along straight lines against a plane. Made from the closest points at the
//! step's start, for a body that goes by the other that plane stands across its path: a
//! bullet 1 cm beside another, metres behind it, met it along a normal nearly along their
//! paths, and both were thrown at 30 m/s; a ball gliding 1 cm over a box's edge met the
//! edge along a normal pointing back along its path, and lost nearly all of its 50 m/s.
//! Made where they come closest, its normal is square to their relative path, its
//! separation the least over the step, and it holds only what else would push them
//! together.

use glam::Vec3;

use super::gjk::{gjk_distance, GjkStatus};
use crate::pose::Pose;
use crate::shape::{ConvexCore, Shape};

/// Halvings of the step in the search for the closest approach. Bounded `[8, 24]`: fewer
/// leave the normal of a near miss more tilted towards the path (harmless, the separation is
/// the least distance, but the contact holds less sideways), more cost GJK runs on every fast
/// pair that comes near another.
const CLOSEST_APPROACH_HALVINGS: u32 = 14;

/// How a pair moves over the step, for [`closest_miss`]: B's displacement relative to A, and
/// how many steps ahead a contact must let the two go.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Passing {
    /// B's displacement relative to A over the step, metres.
    pub closing: Vec3,
    /// One step and a substep (see [`closest_miss`]).
    pub ahead: f32,
}

impl Passing {
    /// The same motion seen from B.
    #[must_use]
    pub fn flipped(self) -> Self {
        Self {
            closing: -self.closing,
            ..self
        }
    }
}

/// The time, in steps, at which the contact of convex shapes `a` at `pa` and `b` at `pb` (at
/// the step's start), `b` moving by `closing` relative to `a` a step, is best made where
/// they do not touch within `passing.ahead` steps: where they come closest, or `ahead` where
/// they are still closing there. `None` where a contact made at the start holds them no
/// closer than their straight paths take them within `ahead` (the common case, one GJK run), where
/// they touch within it (a hit, whose contact is made at the start as for any pair), or
/// where a shape is not convex. `ahead` is one step and a substep: the
/// solver's relax passes after the step's last move hold a speculative point to what it may
/// close in one more substep (a ball gliding 1 cm over a box's edge at 2 m/s, 4 substeps,
/// whose start contact let it close all but 2 mm of its plane in the step, was thrown up at
/// 0.3 m/s).
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
    passing: Passing,
) -> Option<f32> {
    let (core_a, radius_a) = a.convex_core()?;
    let (core_b, radius_b) = b.convex_core()?;
    closest_miss_of_cores((&core_a, radius_a, pa), (&core_b, radius_b, pb), passing)
}

/// [`closest_miss`] of two convex cores with their radii and poses (a mesh's triangle, say).
#[must_use]
pub(crate) fn closest_miss_of_cores(
    (core_a, radius_a, pa): (&ConvexCore<'_>, f32, &Pose),
    (core_b, radius_b, pb): (&ConvexCore<'_>, f32, &Pose),
    Passing { closing, ahead }: Passing,
) -> Option<f32> {
    // The shapes with B moved by `t` of the step: `None` where they overlap, else the normal
    // from A to B at their closest points (the distance falls while `closing · n < 0`) and
    // the distance.
    let normal_at = |t: f32| {
        let moved = Pose::new(pb.translation + closing * t, pb.rotation);
        let g = gjk_distance(core_a, pa, core_b, &moved);
        let gap = g.distance - radius_a - radius_b;
        (g.status != GjkStatus::Overlapping && gap > 0.0).then_some((g.normal, gap))
    };
    let falls = |n: Vec3| n.dot(closing) < 0.0;
    let (mut n_lo, gap) = normal_at(0.0)?;
    if -n_lo.dot(closing) * ahead <= gap {
        // The start's contact lets them go all the way.
        return None;
    }
    let mut n_hi = normal_at(ahead).map(|(n, _)| n);
    if n_hi.is_some_and(falls) {
        return Some(ahead);
    }
    // Invariant: at `lo` apart and closing; at `hi` touching (`None`), or apart and receding.
    let (mut lo, mut hi) = (0.0f32, ahead);
    for _ in 0..CLOSEST_APPROACH_HALVINGS {
        let mid = 0.5 * (lo + hi);
        match normal_at(mid).map(|(n, _)| n) {
            Some(n) if falls(n) => (lo, n_lo) = (mid, n),
            n => (hi, n_hi) = (mid, n),
        }
    }
    // Past a closest approach the normal has barely turned; past a body gone through the
    // other between two tries (thinner than a try's motion), it has turned over: a hit.
    n_hi.filter(|n| n.dot(n_lo) > 0.0).map(|_| hi)
}
