//! Shape-pair dispatch: picks the analytic or generic routine for each pair ([`collide`]).

use glam::Vec3;

use super::box_box::box_box;
use super::capsule_contacts::{capsule_capsule, capsule_sphere};
use super::closest_approach::Passing;
use super::convex_convex::{convex_convex, ClipScratch};
use super::half_space_contacts::half_space_convex;
use super::narrow_stats::NarrowStats;
use super::raw_manifold::{RawManifold, ReduceFrom};
use super::sphere_box::box_sphere;
use super::sphere_sphere::sphere_sphere;
use super::trimesh_contacts::trimesh_convex;
use crate::pose::Pose;
use crate::shape::Shape;

/// Scratch state reused by the collision routines.
#[derive(Debug, Default)]
pub(crate) struct CollideScratch {
    pub(crate) clip: ClipScratch,
    pub(crate) feature: Vec<Vec3>,
}

/// Contact manifolds between shape A at `pa` and shape B at `pb` (poses in any common frame;
/// the caller passes a frame centred near A for precision). Normals point from A to B.
/// Only contacts with separation at most `margin` are produced, each manifold reduced to
/// four points starting `from` (see [`RawManifold::reduce`]). With `passing` (B's motion
/// relative to A over the step), a mesh's triangles that B only goes by are left out (see
/// [`trimesh_convex`]).
#[allow(clippy::too_many_arguments)]
pub(crate) fn collide(
    a: &Shape,
    pa: &Pose,
    b: &Shape,
    pb: &Pose,
    margin: f32,
    from: ReduceFrom,
    passing: Option<Passing>,
    out: &mut Vec<RawManifold>,
    stats: &mut NarrowStats,
    scratch: &mut CollideScratch,
) {
    use Shape as S;
    let start = out.len();
    let flipped = match (a, b) {
        (S::HalfSpace(_), S::HalfSpace(_) | S::TriMesh(_))
        | (S::TriMesh(_), S::HalfSpace(_) | S::TriMesh(_)) => false,
        (S::Sphere(x), S::Sphere(y)) => {
            out.extend(sphere_sphere(
                pa.translation,
                x.radius,
                pb.translation,
                y.radius,
                margin,
            ));
            false
        }
        (S::Cuboid(x), S::Sphere(y)) => {
            out.extend(box_sphere(
                x.half_extents,
                pa,
                pb.translation,
                y.radius,
                margin,
            ));
            false
        }
        (S::Sphere(_), S::Cuboid(_))
        | (S::Sphere(_) | S::Cuboid(_) | S::Capsule(_) | S::ConvexHull(_), S::HalfSpace(_))
        | (S::Sphere(_), S::Capsule(_))
        | (S::Sphere(_) | S::Cuboid(_) | S::Capsule(_) | S::ConvexHull(_), S::TriMesh(_)) => {
            let passing = passing.map(Passing::flipped);
            collide(b, pb, a, pa, margin, from, passing, out, stats, scratch);
            true
        }
        (S::Cuboid(x), S::Cuboid(y)) => {
            let mut tmp = (
                std::mem::take(&mut scratch.clip.a),
                std::mem::take(&mut scratch.clip.b),
            );
            out.extend(box_box(
                x.half_extents,
                pa,
                y.half_extents,
                pb,
                margin,
                &mut tmp,
            ));
            scratch.clip.a = tmp.0;
            scratch.clip.b = tmp.1;
            false
        }
        (S::HalfSpace(h), _) => {
            if let Some((core, r)) = b.convex_core() {
                out.extend(half_space_convex(
                    h.normal,
                    pa,
                    &core,
                    pb,
                    r,
                    margin,
                    &mut scratch.feature,
                ));
            }
            false
        }
        (S::Capsule(x), S::Sphere(y)) => {
            let (s0, s1) = x.segment();
            out.extend(capsule_sphere(
                pa.transform_point(s0),
                pa.transform_point(s1),
                x.radius,
                pb.translation,
                y.radius,
                margin,
            ));
            false
        }
        (S::Capsule(x), S::Capsule(y)) => {
            let (a0, a1) = x.segment();
            let (b0, b1) = y.segment();
            out.extend(capsule_capsule(
                pa.transform_point(a0),
                pa.transform_point(a1),
                x.radius,
                pb.transform_point(b0),
                pb.transform_point(b1),
                y.radius,
                margin,
            ));
            false
        }
        (S::TriMesh(m), _) => {
            trimesh_convex(m, pa, b, pb, margin, passing, out, stats, &mut scratch.clip);
            false
        }
        _ => {
            if let (Some((ca, ra)), Some((cb, rb))) = (a.convex_core(), b.convex_core()) {
                out.extend(convex_convex(
                    &ca,
                    pa,
                    ra,
                    &cb,
                    pb,
                    rb,
                    margin,
                    stats,
                    &mut scratch.clip,
                ));
            }
            false
        }
    };
    for m in &mut out[start..] {
        m.reduce(from);
        if flipped {
            m.flip();
        }
    }
}
