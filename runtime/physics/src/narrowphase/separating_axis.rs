//! Separating axes of placed convex cores, measured from support points: robust where GJK's
//! normal is not (a core kilometres across, a small one barely touching it). Shared by the
//! contact generation ([`super::convex_convex`]) and continuous collision.

use glam::Vec3;

use super::gjk::{gjk_distance, support, GjkResult, GjkStatus};
use crate::pose::Pose;
use crate::shape::ConvexCore;

/// How far apart A and B are along `normal` (world, pointing from A to B), metres: the gap
/// between A's furthest point along it and B's nearest (negative when they overlap). A lower
/// bound on their distance for any axis, exact along the separating one.
pub(crate) fn separation_along(
    a: &ConvexCore<'_>,
    pa: &Pose,
    b: &ConvexCore<'_>,
    pb: &Pose,
    normal: Vec3,
) -> f32 {
    -normal.dot(support(a, pa, b, pb, normal).w)
}

/// A lower bound on the distance of two placed convex cores (with radii), and the normal
/// from A to B it was measured along: the largest separation, from support points, along
/// the GJK normal and the face normals of both cores (negative when overlapping).
///
/// Any axis gives a lower bound; the face normals make it tight where GJK's is not. A wall
/// kilometres wide turns GJK's normal by 1e-4 rad of rounding, which along the wall's far
/// corners is a separation off by most of a metre.
pub(crate) fn convex_gap(
    a: &ConvexCore<'_>,
    pa: &Pose,
    ra: f32,
    b: &ConvexCore<'_>,
    pb: &Pose,
    rb: f32,
) -> (f32, Vec3) {
    convex_gap_after(&gjk_distance(a, pa, b, pb), a, pa, ra, b, pb, rb)
}

/// [`convex_gap`] from GJK's result `g` for the same cores and poses (the contact generation
/// has run it already).
pub(crate) fn convex_gap_after(
    g: &GjkResult,
    a: &ConvexCore<'_>,
    pa: &Pose,
    ra: f32,
    b: &ConvexCore<'_>,
    pb: &Pose,
    rb: f32,
) -> (f32, Vec3) {
    let along = |n: Vec3| separation_along(a, pa, b, pb, n);
    let mut best = if g.status == GjkStatus::Overlapping || g.normal == Vec3::ZERO {
        (
            f32::MIN,
            (pb.translation - pa.translation).normalize_or(Vec3::X),
        )
    } else {
        (along(g.normal).min(g.distance), g.normal)
    };
    // B's faces (outward f: A beyond them along n = −f) and A's (n = f).
    for_each_face_normal(b, pb, |f| {
        let gap = along(-f);
        if gap > best.0 {
            best = (gap, -f);
        }
    });
    for_each_face_normal(a, pa, |f| {
        let gap = along(f);
        if gap > best.0 {
            best = (gap, f);
        }
    });
    if best.0 == f32::MIN {
        best.0 = 0.0;
    }
    (best.0 - ra - rb, best.1)
}

/// Calls `f` with the world outward face normals of a polytope core (both sides of a
/// triangle); curved cores have none.
pub(crate) fn for_each_face_normal(core: &ConvexCore<'_>, pose: &Pose, mut f: impl FnMut(Vec3)) {
    match core {
        ConvexCore::Cuboid(_) => {
            for axis in [Vec3::X, Vec3::Y, Vec3::Z] {
                let n = pose.rotation * axis;
                f(n);
                f(-n);
            }
        }
        ConvexCore::Hull(h) => {
            for face in h.faces() {
                f(pose.rotation * face.normal);
            }
        }
        ConvexCore::Triangle(t) => {
            let n = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero();
            if n != Vec3::ZERO {
                let n = pose.rotation * n;
                f(n);
                f(-n);
            }
        }
        ConvexCore::Point | ConvexCore::Segment(..) => {}
    }
}
