//! Shape casts on [`PhysicsWorld`]: the first collider a shape meets when swept along a
//! straight line ([`PhysicsWorld::cast_shape`]), found by conservative advancement over the
//! narrowphase's own contact routines (exact gaps, never bounding boxes).

use glam::Vec3;

use super::query_filter::QueryFilter;
use crate::aabb::Aabb;
use crate::body_handle::BodyHandle;
use crate::collider::Collider;
use crate::collider_handle::ColliderHandle;
use crate::narrowphase::collide::{collide, CollideScratch};
use crate::narrowphase::raw_manifold::{RawManifold, ReduceFrom};
use crate::narrowphase::NarrowStats;
use crate::physics_world::PhysicsWorld;
use crate::pose::Pose;
use crate::shape::Shape;

/// Most advancement steps of one shape cast against one collider. Flat faces meet in one or
/// two; rounded or tilted ones in a handful. Reaching the cap reports the hit where the cast
/// stopped with [`ShapeHit::converged`] false (a distance the shape can safely travel).
pub const SHAPE_CAST_MAX_ITERATIONS: u32 = 32;

/// A gap within this of the asked-for one counts as the hit, metres. Lower costs steps on
/// rounded shapes; higher leaves the shape that much short of the surface.
pub const SHAPE_CAST_TOLERANCE: f32 = 1e-4;

/// Below this closing rate (the direction's component along a contact normal) a contact is
/// taken as sliding past, not approaching.
const MIN_CLOSING: f32 = 1e-6;

/// What a shape cast met first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeHit {
    /// The collider met.
    pub collider: ColliderHandle,
    /// Its body.
    pub body: BodyHandle,
    /// Distance travelled along the (unit) direction before the gap closed, metres.
    pub distance: f32,
    /// Where they meet, world space (between the two surfaces).
    pub point: Vec3,
    /// The surface normal of the collider met, facing the cast shape.
    pub normal: Vec3,
    /// The search ended within [`SHAPE_CAST_MAX_ITERATIONS`]; `false` means `distance` is
    /// a safe lower bound rather than the exact contact.
    pub converged: bool,
}

impl PhysicsWorld {
    /// Sweeps `shape` from `pose` along `direction` (normalised here) for up to
    /// `max_distance` metres and returns the first collider it comes within `gap` metres of
    /// (`gap` 0: touching). The shape does not turn.
    ///
    /// Contacts the shape only slides along or moves away from do not stop it, so a shape
    /// resting on a floor can be cast sideways, and one that starts overlapping a collider
    /// can be cast out of it; a shape that starts overlapping and moves further in hits at
    /// distance 0. `None` also for a zero or non-finite direction.
    #[must_use]
    pub fn cast_shape(
        &self,
        shape: &Shape,
        pose: &Pose,
        direction: Vec3,
        max_distance: f32,
        gap: f32,
        filter: &QueryFilter,
    ) -> Option<ShapeHit> {
        let dir = direction.try_normalize()?;
        if !(max_distance >= 0.0 && max_distance.is_finite() && pose.translation.is_finite()) {
            return None;
        }
        let gap = gap.max(0.0);
        let reach = Vec3::splat(gap + SHAPE_CAST_TOLERANCE);
        let start = shape.aabb(pose);
        let end = shape.aabb(&Pose::new(
            pose.translation + dir * max_distance,
            pose.rotation,
        ));
        let swept = Aabb::new(
            start.min.min(end.min) - reach,
            start.max.max(end.max) + reach,
        );
        let mut scratch = CastScratch::default();
        let mut best: Option<ShapeHit> = None;
        self.broadphase.tree.query(&swept, |_, data| {
            let Some(c) = self.colliders.arena.get_by_index(data) else {
                return true;
            };
            let body = self.bodies.get(c.parent);
            if !filter.accepts(c, body) || !c.aabb.intersects(&swept) {
                return true;
            }
            let Some(b) = body else { return true };
            let limit = best.map_or(max_distance, |h| h.distance);
            let cast = Cast {
                shape,
                pose,
                dir,
                max_distance: limit,
                gap,
            };
            if let Some((distance, point, normal, converged)) =
                cast.against(c, &b.pose.mul_pose(&c.local_pose), &mut scratch)
            {
                if best.is_none_or(|h| distance < h.distance) {
                    best = Some(ShapeHit {
                        collider: self.colliders.handle_of(data),
                        body: c.parent,
                        distance,
                        point,
                        normal,
                        converged,
                    });
                }
            }
            true
        });
        best
    }
}

#[derive(Default)]
struct CastScratch {
    manifolds: Vec<RawManifold>,
    stats: NarrowStats,
    collide: CollideScratch,
}

/// One sweep, tried against one collider at a time.
struct Cast<'a> {
    shape: &'a Shape,
    pose: &'a Pose,
    dir: Vec3,
    max_distance: f32,
    gap: f32,
}

impl Cast<'_> {
    /// `(distance, point, normal, converged)` of the first approach to within `gap` of `c`
    /// at `pose`, if within `max_distance`.
    fn against(
        &self,
        c: &Collider,
        pose: &Pose,
        scratch: &mut CastScratch,
    ) -> Option<(f32, Vec3, Vec3, bool)> {
        // A frame centred at the cast's start, for precision far from the origin.
        let origin = self.pose.translation;
        let other = Pose::new(pose.translation - origin, pose.rotation);
        let mut t = 0.0f32;
        for _ in 0..SHAPE_CAST_MAX_ITERATIONS {
            let at = Pose::new(self.dir * t, self.pose.rotation);
            scratch.manifolds.clear();
            let margin = self.max_distance - t + self.gap + SHAPE_CAST_TOLERANCE;
            collide(
                self.shape,
                &at,
                &c.shape,
                &other,
                margin,
                ReduceFrom::Deepest,
                None,
                &mut scratch.manifolds,
                &mut scratch.stats,
                &mut scratch.collide,
            );
            // The approaching contact that closes to the gap soonest.
            let mut next: Option<(f32, f32, Vec3, Vec3)> = None;
            for m in &scratch.manifolds {
                let closing = m.normal.dot(self.dir);
                if closing <= MIN_CLOSING {
                    continue;
                }
                for p in &m.points {
                    let advance = (p.separation - self.gap) / closing;
                    if next.is_none_or(|n| advance < n.0) {
                        next = Some((advance, p.separation, p.point, -m.normal));
                    }
                }
            }
            let (advance, separation, point, normal) = next?;
            if separation - self.gap <= SHAPE_CAST_TOLERANCE {
                return Some((t, point + origin, normal, true));
            }
            t += advance.max(0.0);
            if t > self.max_distance {
                return None;
            }
        }
        let at = self.pose.translation + self.dir * t;
        Some((t, at, -self.dir, false))
    }
}
