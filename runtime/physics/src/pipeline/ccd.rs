//! Continuous collision: the earliest time of impact of a body's motion over the step
//! against every collider it could meet (static, kinematic or dynamic, of any shape), by
//! conservative advancement ([`sweep_body`]).
//!
//! Each body moves from its pose at step start to the pose the solver gives it: the centre of
//! mass along a straight line, the rotation by a slerp. For a pair, conservative
//! advancement steps time forward by `(d − target/2) / μ`, where `d` is a lower bound on the
//! distance and `μ` bounds how fast the two can close over the step (the normal part of the
//! relative translation plus each body's turn times the reach of its core). The bodies
//! therefore never get closer than `target/2` at any time the search visits: the time of
//! impact is kept outside the surface with that margin, and the contact solver takes over at
//! the next step from a pose that is not inside the other shape.
//!
//! The distance is the separation along the GJK normal computed from support points
//! (`min_B n·x − max_A n·x`), not GJK's own distance: it is a lower bound on the true
//! distance whatever the normal's rounding, and it stays exact for walls kilometres wide,
//! whose GJK simplices lose millimetres to cancellation (a bullet's time of impact used to
//! land inside a 200 m wall and the next step pushed it out of the back).
//!
//! A body already within `target` of the other at step start (resting on it, or stopped
//! there by last step's time of impact), or into it by less than half of that, is checked
//! against going deeper: its translation may take it `target / 2` deeper than it started
//! (than touching, from a gap), an overlap the contact solver parts at the next step. (Allowed to close only half
//! its gap, two bodies pushed together by a moving wall stopped each other at every step's
//! start, and the wall went through them.) A body that starts overlapping is swept as its
//! inner core (a ball of [`CCD_CORE_FRACTION`] of its smallest half extent at its centre), or
//! as its centre alone when that core overlaps too, so even a deep contact the solver failed
//! to stop cannot carry it through.

use glam::{Quat, Vec3};

use crate::aabb::Aabb;
use crate::body_handle::BodyHandle;
use crate::body_set::BodySet;
use crate::broadphase::BroadPhase;
use crate::collider::Collider;
use crate::collider_set::ColliderSet;
use crate::material::Material;
use crate::narrowphase::separating_axis::convex_gap;
use crate::pose::Pose;
use crate::shape::{ConvexCore, Shape};

/// Iteration cap of one conservative-advancement search. Bounded `[8, 256]`: a bullet
/// meets a wall in 2–4 iterations, a fast-turning box in 10–30. Hitting the cap is counted
/// in `StepCounters::ccd_not_converged`; the body is then stopped where the search got to
/// (which is still outside the other shape).
pub const CCD_MAX_ITERATIONS: u32 = 64;

/// CCD runs only when the step's motion (translation plus turn times reach) exceeds this
/// fraction of the body's smallest bounding half extent (slower bodies are handled by
/// speculative contacts).
pub const CCD_MOTION_THRESHOLD: f32 = 0.5;

/// Stop distance of the time of impact as a fraction of the body's smallest half extent,
/// when that is less than `PhysicsSettings::linear_slop` (a 1 mm bullet is not stopped a
/// whole slop short of the wall).
pub const CCD_TARGET_SIZE_FRACTION: f32 = 0.1;

/// Radius of the inner core swept for a body that starts overlapping, as a fraction of its
/// smallest half extent. Bounded `(0, 1)`: larger cores catch shallower overlaps, smaller
/// ones let the core start clear of deeper ones.
pub const CCD_CORE_FRACTION: f32 = 0.5;

/// How a body moves over the step: its centre of mass along a line, its rotation by slerp.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct BodyMotion {
    pub com0: Vec3,
    pub com1: Vec3,
    pub q0: Quat,
    pub q1: Quat,
    /// Centre of mass in the body frame.
    pub local_com: Vec3,
}

impl BodyMotion {
    /// A body that does not move.
    pub fn fixed(pose: &Pose, local_com: Vec3) -> Self {
        let com = pose.transform_point(local_com);
        Self {
            com0: com,
            com1: com,
            q0: pose.rotation,
            q1: pose.rotation,
            local_com,
        }
    }

    /// From the pose at step start to the pose at its end.
    pub fn between(start: &Pose, end: &Pose, local_com: Vec3) -> Self {
        let q1 = if start.rotation.dot(end.rotation) < 0.0 {
            -end.rotation
        } else {
            end.rotation
        };
        Self {
            com0: start.transform_point(local_com),
            com1: end.transform_point(local_com),
            q0: start.rotation,
            q1,
            local_com,
        }
    }

    /// Body pose at fraction `t` of the step, with translations taken relative to `origin`.
    pub fn pose_at(&self, t: f32, origin: Vec3) -> Pose {
        let q = if self.q0 == self.q1 {
            self.q0
        } else {
            self.q0.slerp(self.q1, t).normalize()
        };
        let com = (self.com0 - origin) + (self.com1 - self.com0) * t;
        Pose::new(com - q * self.local_com, q)
    }

    /// Angle turned over the step, radians.
    pub fn turn(&self) -> f32 {
        let d = (self.q1 * self.q0.inverse()).normalize();
        2.0 * d.w.abs().min(1.0).acos()
    }

    /// Displacement of the centre of mass over the step.
    pub fn displacement(&self) -> Vec3 {
        self.com1 - self.com0
    }
}

/// One collider a sweep found in the body's way.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SweepHit {
    /// Fraction of the step the body may move (`< 1`).
    pub t: f32,
    /// The body hit.
    pub body: BodyHandle,
    /// The hit came from a start in contact or in overlap, where the search bounds the
    /// translation only (see [`Pair::time_of_impact`]).
    pub from_contact: bool,
    /// Unit normal of the hit, from the swept body towards the one hit.
    pub normal: Vec3,
    /// Combined restitution of the two colliders.
    pub restitution: f32,
}

/// What a sweep found.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub(crate) struct Sweep {
    /// The first hit.
    pub first: Option<SweepHit>,
    /// The first hit of a body that does not stop itself (static, kinematic, or dynamic
    /// without CCD): where the body stops when it need not stop for a dynamic body with CCD
    /// met earlier (see `PhysicsWorld::carried_by_slow_bodies`).
    pub first_unswept: Option<SweepHit>,
    /// Some search hit [`CCD_MAX_ITERATIONS`].
    pub not_converged: bool,
}

/// What one pair search found (see [`Pair::time_of_impact`]).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Impact {
    /// Fraction of the step until the pair comes within the stop distance (1: never).
    t: f32,
    /// The search hit [`CCD_MAX_ITERATIONS`].
    capped: bool,
    /// The pair started in contact or overlap.
    from_contact: bool,
    /// Unit normal from the swept body towards the other at the stop.
    normal: Vec3,
}

impl Impact {
    const NONE: Self = Self {
        t: 1.0,
        capped: false,
        from_contact: false,
        normal: Vec3::ZERO,
    };
}

/// How a body CCD stopped is carried over the rest of the step by the body it hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Carry {
    /// Not at all: the body hit stops too (dynamic, with CCD).
    Stopped,
    /// By this displacement over the whole step, of the body hit as it goes on moving (a
    /// wall moving into a bullet carries it along).
    By(Vec3),
    /// By the displacement over the whole step of a much slower body with CCD, of this solver
    /// index, where it ends (`PhysicsWorld::carried_by_slow_bodies`): its own stop, and what
    /// carries it, included.
    With(u32),
    /// By the whole rigid motion of a turning kinematic body (a spinning paddle's point
    /// moves, its centre need not).
    Rigid(BodyMotion),
}

impl Carry {
    /// Whether it moves the stopped body at all.
    pub fn moves(&self) -> bool {
        match self {
            Self::Stopped => false,
            Self::By(d) => *d != Vec3::ZERO,
            Self::With(_) | Self::Rigid(_) => true,
        }
    }
}

/// A body CCD stopped short of where the solver left it, as the write-back applies it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CcdClamp {
    /// Solver index of the body.
    pub body: u32,
    /// Fraction of its motion it keeps.
    pub t: f32,
    /// How the body hit carries this one over the rest of the step.
    pub carry: Carry,
    /// [`SweepHit::from_contact`].
    pub from_contact: bool,
    /// The body hit.
    pub hit: BodyHandle,
    /// [`SweepHit::normal`].
    pub normal: Vec3,
    /// [`SweepHit::restitution`].
    pub restitution: f32,
    /// [`Sweep::first_unswept`], where that is not the hit.
    pub fallback: Option<SweepHit>,
}

/// One collider of the swept body, ready for the pair searches.
struct Mover<'a> {
    /// Its core (or the inner core for a start in overlap) and radius.
    core: ConvexCore<'a>,
    radius: f32,
    /// Collider pose relative to the body frame (a shifted one for the inner core).
    local: Pose,
    /// Largest distance from the centre of mass to the core, metres.
    reach: f32,
}

/// Earliest fraction `t` in `[0, 1]` of the body's motion at which one of its convex
/// colliders comes within the stop distance of another collider (see the module docs).
/// `motion_of` gives the motion of any other body over the step; `others_move` is the largest
/// displacement of any body this step (the broadphase holds their bounds at step start), and
/// `driven` the largest of a kinematic body's, its turn times its reach included: a body at
/// rest is swept too where a kinematic body moves that far (a wall at 50 m/s passed over
/// balls at rest with CCD on).
#[allow(clippy::too_many_arguments)]
pub(crate) fn sweep_body(
    colliders: &ColliderSet,
    bodies: &BodySet,
    bp: &BroadPhase,
    body: BodyHandle,
    motion: &BodyMotion,
    linear_slop: f32,
    others_move: f32,
    driven: f32,
    motion_of: &dyn Fn(BodyHandle) -> Option<BodyMotion>,
) -> Sweep {
    let mut out = Sweep::default();
    let Some(b) = bodies.get(body) else {
        return out;
    };
    let turn = motion.turn();
    let disp = motion.displacement();
    let origin = motion.com0;
    for &ch in &b.colliders {
        let Some(c) = colliders.get(ch) else {
            continue;
        };
        if c.sensor {
            continue;
        }
        let Some((core, radius)) = c.shape.convex_core() else {
            continue;
        };
        let local_box = c.shape.aabb(&Pose::IDENTITY);
        let min_half = local_box.half_extents().min_element();
        let centre_offset = c.local_pose.translation - motion.local_com;
        let reach = centre_offset.length() + core.reach();
        let bound = centre_offset.length() + local_box.half_extents().length();
        if disp.length() + turn * reach + driven < CCD_MOTION_THRESHOLD * min_half {
            continue;
        }
        let target = linear_slop.min(CCD_TARGET_SIZE_FRACTION * min_half);
        // Everything the collider's bounding sphere sweeps over.
        let swept = Aabb::from_center_half(motion.com0, Vec3::splat(bound))
            .union(&Aabb::from_center_half(motion.com1, Vec3::splat(bound)));
        let mover = Mover {
            core,
            radius,
            local: c.local_pose,
            reach,
        };
        bp.tree.query(&swept.expanded(others_move), |_, data| {
            let Some(other) = colliders.arena.get_by_index(data) else {
                return true;
            };
            if other.parent == body || other.sensor {
                return true;
            }
            let Some(other_motion) = motion_of(other.parent) else {
                return true;
            };
            // A pair moving together (bodies a kinematic wall carries, side by side) closes
            // less than the threshold of the smaller of the two: its contacts hold it. Its
            // time of impact stopped both part way through the step, and the wall that
            // carried them went on through them.
            let other_turn_reach = other_reach(other, &other_motion);
            let relative = (disp - other_motion.displacement()).length()
                + turn * reach
                + other_motion.turn() * other_turn_reach;
            let other_half = other
                .shape
                .aabb(&Pose::IDENTITY)
                .half_extents()
                .min_element();
            if relative < CCD_MOTION_THRESHOLD * min_half.min(other_half) {
                return true;
            }
            if other_motion.com0 != other_motion.com1 {
                // A moving body: its own swept bounds must meet ours.
                let start = other_motion
                    .pose_at(0.0, Vec3::ZERO)
                    .mul_pose(&other.local_pose);
                let end = other_motion
                    .pose_at(1.0, Vec3::ZERO)
                    .mul_pose(&other.local_pose);
                let theirs = other.shape.aabb(&start).union(&other.shape.aabb(&end));
                let reach = other_turn_reach * other_motion.turn().min(2.0);
                if !theirs.expanded(reach).intersects(&swept) {
                    return true;
                }
            }
            let pair = Pair {
                a: &mover,
                a_motion: motion,
                b: other,
                b_motion: &other_motion,
                origin,
                swept: &swept,
            };
            // Hits of bodies that stop themselves count only before every other hit; the
            // others before the first of their own kind.
            let swept_other = bodies.get(other.parent).is_some_and(|o| o.swept());
            let t_of = |h: Option<SweepHit>| h.map_or(1.0, |h| h.t);
            let t_max = if swept_other {
                t_of(out.first)
            } else {
                t_of(out.first_unswept)
            };
            let hit = pair.time_of_impact(target, t_max, local_box);
            out.not_converged |= hit.capped;
            if hit.t < t_max {
                let found = Some(SweepHit {
                    t: hit.t,
                    body: other.parent,
                    from_contact: hit.from_contact,
                    normal: hit.normal,
                    restitution: Material::combine(&c.material, &other.material).0,
                });
                if !swept_other {
                    out.first_unswept = found;
                }
                if hit.t < t_of(out.first) {
                    out.first = found;
                }
            }
            true
        });
    }
    out
}

/// The swept collider against one other collider.
struct Pair<'a> {
    a: &'a Mover<'a>,
    a_motion: &'a BodyMotion,
    b: &'a Collider,
    b_motion: &'a BodyMotion,
    /// World point all poses are taken relative to (the swept body's start).
    origin: Vec3,
    swept: &'a Aabb,
}

impl Pair<'_> {
    /// The fraction of the step until the pair comes within `target` (at most `t_max`) and
    /// the normal there, whether the search was capped, and whether the pair started in
    /// contact or overlap (the search then bounds the translation only).
    fn time_of_impact(&self, target: f32, t_max: f32, local_box: Aabb) -> Impact {
        let a = self.a;
        let Some((d0, _)) = self.distance(0.0, &a.core, a.radius, &a.local) else {
            return Impact::NONE;
        };
        if d0 > target {
            return self.advance(
                target,
                0.5 * target,
                t_max,
                &a.core,
                a.radius,
                &a.local,
                true,
            );
        }
        if d0 > -0.5 * target {
            // Touching at step start, or overlapping by less than the stop distance: it may
            // slide along, and go into an overlap at most half the stop distance deeper,
            // which the contact solver pushes out at the next step.
            let from = d0.min(0.0);
            return Impact {
                from_contact: true,
                ..self.advance(
                    from - 0.5 * target,
                    from - target,
                    t_max,
                    &a.core,
                    a.radius,
                    &a.local,
                    false,
                )
            };
        }
        // Overlapping at step start: sweep the inner core.
        let half = local_box.half_extents();
        let centre = match a.core {
            ConvexCore::Hull(h) => {
                h.vertices().iter().copied().sum::<Vec3>() / h.vertices().len().max(1) as f32
            }
            _ => local_box.center(),
        };
        // The inner core, or failing that (it overlaps too) the centre alone.
        let local = a.local.mul_pose(&Pose::from_translation(centre));
        for core_radius in [CCD_CORE_FRACTION * half.min_element(), 0.0] {
            if let Some((dc, _)) = self.distance(0.0, &ConvexCore::Point, core_radius, &local) {
                if dc > 0.0 {
                    let core_target = target.min(0.5 * dc);
                    return Impact {
                        from_contact: true,
                        ..self.advance(
                            core_target,
                            0.5 * core_target,
                            t_max,
                            &ConvexCore::Point,
                            core_radius,
                            &local,
                            false,
                        )
                    };
                }
            }
        }
        Impact {
            from_contact: true,
            ..Impact::NONE
        }
    }

    /// Conservative advancement from `t = 0` until the distance is at most `stop`, each step
    /// aiming at `aim` (< `stop`, so that the search ends in few steps; the distance never
    /// falls below `aim` at any time it visits). With `turning`, the closing-speed bound
    /// includes both bodies' turns (the bodies start apart); without it only their
    /// translations (a start in contact, where the solver owns the small motions a turn makes).
    #[allow(clippy::too_many_arguments)]
    fn advance(
        &self,
        stop: f32,
        aim: f32,
        t_max: f32,
        core: &ConvexCore<'_>,
        radius: f32,
        local: &Pose,
        turning: bool,
    ) -> Impact {
        let rel = self.a_motion.displacement() - self.b_motion.displacement();
        let spin = if turning {
            self.a_motion.turn() * self.a.reach
                + self.b_motion.turn() * other_reach(self.b, self.b_motion)
        } else {
            0.0
        };
        let mut t = 0.0f32;
        let mut normal = Vec3::ZERO;
        for _ in 0..CCD_MAX_ITERATIONS {
            let Some((d, n)) = self.distance(t, core, radius, local) else {
                return Impact::NONE;
            };
            normal = n;
            if d <= stop {
                return Impact {
                    t,
                    normal,
                    ..Impact::NONE
                };
            }
            // n points from A to B: A closes along +n.
            let mu = n.dot(rel) + spin;
            if mu <= 0.0 {
                return Impact::NONE;
            }
            let next = t + (d - aim) / mu;
            if next >= t_max {
                return Impact::NONE;
            }
            t = next;
        }
        Impact {
            t,
            capped: true,
            from_contact: false,
            normal,
        }
    }

    /// A lower bound on the distance from A's core (with `radius`, at body-relative `local`)
    /// to B at fraction `t`, and the unit normal from A to B; `None` when B cannot be
    /// measured against (nothing to hit).
    fn distance(
        &self,
        t: f32,
        core: &ConvexCore<'_>,
        radius: f32,
        local: &Pose,
    ) -> Option<(f32, Vec3)> {
        let pa = self.a_motion.pose_at(t, self.origin).mul_pose(local);
        let pb = self
            .b_motion
            .pose_at(t, self.origin)
            .mul_pose(&self.b.local_pose);
        match &self.b.shape {
            Shape::HalfSpace(h) => {
                let n = pb.rotation * h.normal;
                let deepest = pa.transform_point(core.support(pa.inverse_transform_vector(-n)));
                Some((n.dot(deepest - pb.translation) - radius, -n))
            }
            Shape::TriMesh(m) => {
                // Triangles near the swept volume, in the mesh frame.
                let rel = self.swept.center() - self.origin;
                let centre = pb.inverse_transform_point(rel);
                let r = glam::Mat3::from_quat(pb.rotation);
                let h = self.swept.half_extents();
                let half = Vec3::new(
                    r.x_axis.abs().dot(h),
                    r.y_axis.abs().dot(h),
                    r.z_axis.abs().dot(h),
                );
                let query = Aabb::from_center_half(centre, half);
                let mut best: Option<(f32, Vec3)> = None;
                m.for_each_in_aabb(&query, |ti| {
                    let tri = ConvexCore::Triangle(m.triangle(ti));
                    let d = convex_gap(core, &pa, radius, &tri, &pb, 0.0);
                    if best.is_none_or(|(bd, _)| d.0 < bd) {
                        best = Some(d);
                    }
                });
                best
            }
            other => {
                let (oc, orad) = other.convex_core()?;
                Some(convex_gap(core, &pa, radius, &oc, &pb, orad))
            }
        }
    }
}

/// Reach of a collider about its body's centre of mass (for the turn bound).
fn other_reach(c: &Collider, m: &BodyMotion) -> f32 {
    if m.q0 == m.q1 {
        return 0.0;
    }
    let core_reach = c.shape.convex_core().map_or_else(
        || c.shape.aabb(&Pose::IDENTITY).half_extents().length(),
        |(core, _)| core.reach(),
    );
    (c.local_pose.translation - m.local_com).length() + core_reach
}
