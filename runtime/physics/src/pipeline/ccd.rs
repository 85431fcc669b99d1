//! Continuous collision: time of impact of a body's translation against static colliders
//! by conservative advancement over GJK distances ([`sweep_body`]).

use glam::Vec3;

use crate::aabb::Aabb;
use crate::body_handle::BodyHandle;
use crate::body_set::BodySet;
use crate::body_type::BodyType;
use crate::broadphase::BroadPhase;
use crate::collider_set::ColliderSet;
use crate::narrowphase::gjk::{gjk_distance, GjkStatus};
use crate::physics_settings::PhysicsSettings;
use crate::pose::Pose;
use crate::shape::{ConvexCore, Shape};

/// Iteration cap of one conservative-advancement search. Bounded `[4, 64]`; hitting it
/// is counted in `StepCounters::ccd_not_converged` and the motion is left unclamped.
pub const CCD_MAX_ITERATIONS: u32 = 32;

/// CCD runs only when the step's motion exceeds this fraction of the body's smallest
/// bounding half extent (slow bodies are handled by speculative contacts).
pub const CCD_MOTION_THRESHOLD: f32 = 0.5;

/// Earliest fraction `t` in `[0, 1]` of the motion from `start` to `end` (translation only;
/// the end rotation is used throughout) at which one of the body's convex colliders comes
/// within `linear_slop` of a static collider. Returns `(1, _)` when nothing is hit, and
/// whether some search hit [`CCD_MAX_ITERATIONS`].
pub(crate) fn sweep_body(
    colliders: &ColliderSet,
    bodies: &BodySet,
    bp: &BroadPhase,
    body: BodyHandle,
    start: &Pose,
    end: &Pose,
    s: &PhysicsSettings,
) -> (f32, bool) {
    let Some(b) = bodies.get(body) else {
        return (1.0, false);
    };
    let motion = end.translation - start.translation;
    let dist = motion.length();
    if dist <= 0.0 {
        return (1.0, false);
    }
    let mut best = 1.0f32;
    let mut not_converged = false;
    for &ch in &b.colliders {
        let Some(c) = colliders.get(ch) else {
            continue;
        };
        let Some((core, radius)) = c.shape.convex_core() else {
            continue;
        };
        let p_start = start.mul_pose(&c.local_pose);
        let p_end = end.mul_pose(&c.local_pose);
        let a0 = c.shape.aabb(&p_start);
        let a1 = c.shape.aabb(&p_end);
        let min_half = a0.half_extents().min_element();
        if dist < CCD_MOTION_THRESHOLD * min_half {
            continue;
        }
        let swept: Aabb = a0.union(&a1);
        bp.tree.query(&swept, |_, data| {
            let Some(other) = colliders.arena.get_by_index(data) else {
                return true;
            };
            if other.parent == body {
                return true;
            }
            let Some(ob) = bodies.get(other.parent) else {
                return true;
            };
            if ob.body_type != BodyType::Static {
                return true;
            }
            let op = ob.pose.mul_pose(&other.local_pose);
            let (t, nc) = toi_against(
                &core,
                radius,
                &p_start,
                motion,
                p_end.rotation,
                &other.shape,
                &op,
                s.linear_slop,
                best,
            );
            not_converged |= nc;
            if t < best {
                best = t;
            }
            true
        });
    }
    (best, not_converged)
}

/// Conservative advancement of a translating core against one shape. Returns `(t, capped)`.
#[allow(clippy::too_many_arguments)]
fn toi_against(
    core: &ConvexCore<'_>,
    radius: f32,
    start: &Pose,
    motion: Vec3,
    rotation: glam::Quat,
    other: &Shape,
    other_pose: &Pose,
    target: f32,
    t_max: f32,
) -> (f32, bool) {
    let len = motion.length();
    // Work relative to the start position for precision.
    let origin = start.translation;
    let op = Pose::new(other_pose.translation - origin, other_pose.rotation);
    let distance = |t: f32| -> Option<f32> {
        let pa = Pose::new(motion * t, rotation);
        match other {
            Shape::HalfSpace(h) => {
                let n = op.rotation * h.normal;
                let deepest = pa.transform_point(core.support(pa.inverse_transform_vector(-n)));
                Some(n.dot(deepest - op.translation) - radius)
            }
            Shape::TriMesh(m) => {
                let rel = op.inv_mul(&pa);
                let cover = Pose::new(rel.translation, rel.rotation);
                let sh_aabb =
                    crate::aabb::Aabb::from_center_half(cover.translation, Vec3::splat(len + 1.0));
                let mut dmin: Option<f32> = None;
                m.for_each_in_aabb(&sh_aabb, |ti| {
                    let tri = ConvexCore::Triangle(m.triangle(ti));
                    let g = gjk_distance(&tri, &op, core, &pa);
                    let d = if g.status == GjkStatus::Overlapping {
                        0.0
                    } else {
                        g.distance
                    } - radius;
                    dmin = Some(dmin.map_or(d, |x: f32| x.min(d)));
                });
                dmin
            }
            _ => {
                let (oc, orad) = other.convex_core()?;
                let g = gjk_distance(core, &pa, &oc, &op);
                let d = if g.status == GjkStatus::Overlapping {
                    0.0
                } else {
                    g.distance
                };
                Some(d - radius - orad)
            }
        }
    };
    let mut t = 0.0f32;
    for _ in 0..CCD_MAX_ITERATIONS {
        let Some(d) = distance(t) else {
            return (1.0, false);
        };
        if d <= target {
            // Already touching at the start: leave it to the contact solver.
            return (if t == 0.0 { 1.0 } else { t }, false);
        }
        t += (d - 0.5 * target) / len;
        if t >= t_max {
            return (1.0, false);
        }
    }
    (1.0, true)
}
