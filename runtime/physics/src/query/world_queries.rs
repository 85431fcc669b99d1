//! Scene queries on [`PhysicsWorld`]: ray casts, shape overlap, AABB overlap.

use glam::Vec3;

use super::query_filter::QueryFilter;
use super::ray_hit::RayHit;
use crate::aabb::Aabb;
use crate::collider_handle::ColliderHandle;
use crate::narrowphase::collide::{collide, CollideScratch};
use crate::narrowphase::raw_manifold::ReduceFrom;
use crate::narrowphase::NarrowStats;
use crate::physics_world::PhysicsWorld;
use crate::pose::Pose;
use crate::shape::Shape;

impl PhysicsWorld {
    fn ray_candidates(
        &self,
        origin: Vec3,
        dir: Vec3,
        max_toi: f32,
        filter: &QueryFilter,
        mut on_hit: impl FnMut(RayHit) -> f32,
    ) {
        self.broadphase
            .tree
            .ray_query(origin, dir, max_toi, |_, data| {
                let mut limit = max_toi;
                let Some(c) = self.colliders.arena.get_by_index(data) else {
                    return limit;
                };
                let body = self.bodies.get(c.parent);
                if !filter.accepts(c, body) {
                    return limit;
                }
                let Some(b) = body else { return limit };
                let pose = b.pose.mul_pose(&c.local_pose);
                // Local ray relative to the shape (precision far from the origin).
                let lo = pose.inverse_transform_point(origin);
                let ld = pose.inverse_transform_vector(dir);
                if let Some((toi, n)) = c.shape.cast_local_ray(lo, ld, max_toi) {
                    limit = on_hit(RayHit {
                        collider: self.colliders.handle_of(data),
                        body: c.parent,
                        toi,
                        point: origin + dir * toi,
                        normal: pose.transform_vector(n),
                    });
                }
                limit
            });
    }

    /// Closest hit of the ray `origin + t · dir`, `t` in `[0, max_toi]`.
    #[must_use]
    pub fn cast_ray(
        &self,
        origin: Vec3,
        dir: Vec3,
        max_toi: f32,
        filter: &QueryFilter,
    ) -> Option<RayHit> {
        let mut best: Option<RayHit> = None;
        self.ray_candidates(origin, dir, max_toi, filter, |h| {
            if best.is_none_or(|b| h.toi < b.toi) {
                best = Some(h);
            }
            best.map_or(max_toi, |b| b.toi)
        });
        best
    }

    /// Every hit along the ray (one per collider), sorted by distance.
    #[must_use]
    pub fn cast_ray_all(
        &self,
        origin: Vec3,
        dir: Vec3,
        max_toi: f32,
        filter: &QueryFilter,
    ) -> Vec<RayHit> {
        let mut hits = Vec::new();
        self.ray_candidates(origin, dir, max_toi, filter, |h| {
            hits.push(h);
            max_toi
        });
        hits.sort_by(|a, b| a.toi.total_cmp(&b.toi));
        hits
    }

    /// Colliders overlapping `shape` placed at `pose` (touching counts).
    #[must_use]
    pub fn intersect_shape(
        &self,
        shape: &Shape,
        pose: &Pose,
        filter: &QueryFilter,
    ) -> Vec<ColliderHandle> {
        let mut out = Vec::new();
        let bounds = shape.aabb(pose);
        let mut stats = NarrowStats::default();
        let mut scratch = CollideScratch::default();
        let mut manifolds = Vec::new();
        self.broadphase.tree.query(&bounds, |_, data| {
            let Some(c) = self.colliders.arena.get_by_index(data) else {
                return true;
            };
            let body = self.bodies.get(c.parent);
            if !filter.accepts(c, body) || !c.aabb.intersects(&bounds) {
                return true;
            }
            let Some(b) = body else { return true };
            let cp = b.pose.mul_pose(&c.local_pose);
            // Frame centred at the query shape.
            let qa = Pose::new(Vec3::ZERO, pose.rotation);
            let qb = Pose::new(cp.translation - pose.translation, cp.rotation);
            manifolds.clear();
            collide(
                shape,
                &qa,
                &c.shape,
                &qb,
                0.0,
                ReduceFrom::Deepest,
                None,
                &mut manifolds,
                &mut stats,
                &mut scratch,
            );
            if manifolds
                .iter()
                .any(|m| m.points.iter().any(|p| p.separation <= 0.0))
            {
                out.push(self.colliders.handle_of(data));
            }
            true
        });
        out
    }

    /// Colliders whose bounds overlap `aabb`.
    #[must_use]
    pub fn intersect_aabb(&self, aabb: &Aabb, filter: &QueryFilter) -> Vec<ColliderHandle> {
        let mut out = Vec::new();
        self.broadphase.tree.query(aabb, |_, data| {
            if let Some(c) = self.colliders.arena.get_by_index(data) {
                if c.aabb.intersects(aabb) && filter.accepts(c, self.bodies.get(c.parent)) {
                    out.push(self.colliders.handle_of(data));
                }
            }
            true
        });
        out
    }
}
