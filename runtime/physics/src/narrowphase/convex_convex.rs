//! Generic convex–convex contact: GJK (separated) or EPA (overlapping) for the normal,
//! then feature clipping for up to four points.

use glam::Vec3;

use super::epa::{epa_penetration, EpaStatus};
use super::gjk::{gjk_distance, support, GjkStatus};
use super::narrow_stats::NarrowStats;
use super::polygon_clip::clip_features;
use super::raw_manifold::RawManifold;
use super::separating_axis::{convex_gap_after, separation_along};
use crate::pose::Pose;
use crate::shape::ConvexCore;

/// Minimum alignment (cosine) between the contact normal and a polygon face for that face
/// to serve as the clipping reference; below it a single GJK/EPA point is used.
pub const CLIP_REFERENCE_MIN_COS: f32 = 0.7;

/// Core distance (metres) below which GJK's answer is treated as touching and EPA supplies
/// the normal instead (a GJK normal from a near-zero vector is noise). Bounded `[1e-7, 1e-3]`.
pub const EPA_SWITCH_DISTANCE: f32 = 1e-5;

/// A core whose reach is more than this many times the other's gets its contact axis from
/// [`convex_gap_after`]: of GJK's normal and the face normals of both cores, the one they are
/// furthest apart along, measured from support points. Bounded `[10, ∞)`: below it GJK's
/// rounding is well under the smaller core's size.
pub const LARGE_CORE_RATIO: f32 = 100.0;

/// Two candidate reference faces whose separations differ by less than this (relative, in
/// metres per metre of separation, plus this in metres) are a tie. Bounded `[0, 1e-3]`.
pub const FACE_CHOICE_TOLERANCE: f32 = 1e-5;

/// Scratch buffers reused across calls.
#[derive(Debug, Default)]
pub(crate) struct ClipScratch {
    pub(crate) a: Vec<Vec3>,
    pub(crate) b: Vec<Vec3>,
}

/// Contact between convex cores A (radius `ra`) and B (radius `rb`).
#[allow(clippy::too_many_arguments)]
pub(crate) fn convex_convex(
    a: &ConvexCore<'_>,
    pa: &Pose,
    ra: f32,
    b: &ConvexCore<'_>,
    pb: &Pose,
    rb: f32,
    margin: f32,
    stats: &mut NarrowStats,
    scratch: &mut ClipScratch,
) -> Option<RawManifold> {
    let g = gjk_distance(a, pa, b, pb);
    stats.gjk_calls += 1;
    stats.gjk_iterations += g.iterations;
    if g.status == GjkStatus::NotConverged {
        stats.gjk_not_converged += 1;
    }
    // A core far larger than the other (a wall kilometres wide, a long triangle) puts
    // GJK's and EPA's simplices kilometres from the contact: their normal is off by 1e-4 rad
    // of rounding or, for a small body barely touching, by tens of degrees (a bullet resting
    // against a 10 km hull wall was pushed sideways instead of back, and crept through it),
    // and GJK's distance, which rounding only lengthens, is no test of being apart: a 10 cm
    // box resting on a triangle 2 km wide, 10 m from its corner, was measured 0.6 m away
    // (past the margin) three steps in four, fell into it and was pushed back out. The face
    // normals of both cores, measured from support points, give the axis and a lower bound
    // on the distance there.
    let (reach_a, reach_b) = (a.reach(), b.reach());
    let (n, sep, wa, wb) = if reach_a.max(reach_b) > LARGE_CORE_RATIO * reach_a.min(reach_b) {
        // The best lower bound on the distance among GJK's normal and the face normals.
        let (gap, axis) = convex_gap_after(&g, a, pa, ra, b, pb, rb);
        if gap > margin {
            return None;
        }
        let s = support(a, pa, b, pb, axis);
        (axis, gap, s.a, s.b)
    } else if g.status != GjkStatus::Overlapping && g.distance > EPA_SWITCH_DISTANCE {
        let sep = g.distance - ra - rb;
        if sep > margin {
            return None;
        }
        (g.normal, sep, g.point_a, g.point_b)
    } else {
        let e = epa_penetration(a, pa, b, pb, &g.simplex);
        stats.epa_calls += 1;
        stats.epa_iterations += e.iterations;
        if e.status != EpaStatus::Converged {
            stats.epa_failures += 1;
        }
        (e.normal, -e.depth - ra - rb, e.point_a, e.point_b)
    };
    let single = || {
        let p = (wa + n * ra + wb - n * rb) * 0.5;
        RawManifold::single(n, p, sep, 0)
    };
    // Supporting features.
    let fa_n = a.support_feature(pa.inverse_transform_vector(n), &mut scratch.a);
    let fb_n = b.support_feature(pb.inverse_transform_vector(-n), &mut scratch.b);
    for p in scratch.a.iter_mut() {
        *p = pa.transform_point(*p);
    }
    for p in scratch.b.iter_mut() {
        *p = pb.transform_point(*p);
    }
    let ca = fa_n.map(|fnrm| (pa.rotation * fnrm).dot(n));
    let cb = fb_n.map(|fnrm| -(pb.rotation * fnrm).dot(n));
    let use_a = match (fa_n, fb_n, ca, cb) {
        // Two faces: the one the shapes are further apart along is the contact's face (the
        // separating-axis choice). Which is closer to the GJK/EPA normal decides only a tie:
        // that normal is noise for shapes that barely touch, and a bullet resting tilted
        // against a wall took its own face as the reference, pushed along it 4.8° off the
        // wall's normal and slid through the wall.
        (Some(na), Some(nb), Some(x), Some(y)) => {
            let sep_a = separation_along(a, pa, b, pb, pa.rotation * na);
            let sep_b = separation_along(a, pa, b, pb, -(pb.rotation * nb));
            if (sep_a - sep_b).abs() > FACE_CHOICE_TOLERANCE * (1.0 + sep_a.abs().max(sep_b.abs()))
            {
                sep_a > sep_b
            } else {
                x + 0.01 >= y
            }
        }
        (_, _, Some(_), None) => true,
        (_, _, None, Some(_)) => false,
        _ => return Some(single()),
    };
    let (cos, ref_n) = if use_a {
        (ca.unwrap_or(0.0), pa.rotation * fa_n.unwrap_or(Vec3::ZERO))
    } else {
        (cb.unwrap_or(0.0), pb.rotation * fb_n.unwrap_or(Vec3::ZERO))
    };
    if cos < CLIP_REFERENCE_MIN_COS {
        return Some(single());
    }
    let mut m = RawManifold::new(if use_a { ref_n } else { -ref_n });
    let added = if use_a {
        clip_features(&scratch.a, ref_n, ra, &scratch.b, rb, margin, 0, &mut m)
    } else {
        clip_features(
            &scratch.b, ref_n, rb, &scratch.a, ra, margin, 0x4000, &mut m,
        )
    };
    if added == 0 {
        return Some(single());
    }
    Some(m)
}
