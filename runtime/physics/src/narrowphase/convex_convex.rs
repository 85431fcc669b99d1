//! Generic convex–convex contact: GJK (separated) or EPA (overlapping) for the normal,
//! then feature clipping for up to four points.

use glam::Vec3;

use super::epa::{epa_penetration, EpaStatus};
use super::gjk::{gjk_distance, GjkStatus};
use super::narrow_stats::NarrowStats;
use super::polygon_clip::clip_features;
use super::raw_manifold::RawManifold;
use crate::pose::Pose;
use crate::shape::ConvexCore;

/// Minimum alignment (cosine) between the contact normal and a polygon face for that face
/// to serve as the clipping reference; below it a single GJK/EPA point is used.
pub const CLIP_REFERENCE_MIN_COS: f32 = 0.7;

/// Core distance (metres) below which GJK's answer is treated as touching and EPA supplies
/// the normal instead (a GJK normal from a near-zero vector is noise). Bounded `[1e-7, 1e-3]`.
pub const EPA_SWITCH_DISTANCE: f32 = 1e-5;

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
    let (n, sep, wa, wb) = if g.status != GjkStatus::Overlapping && g.distance > EPA_SWITCH_DISTANCE
    {
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
    let use_a = match (ca, cb) {
        (Some(x), Some(y)) => x + 0.01 >= y,
        (Some(_), None) => true,
        (None, Some(_)) => false,
        (None, None) => return Some(single()),
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
    m.reduce();
    Some(m)
}
