//! [`ColliderDesc`]: builder for colliders.

use std::sync::Arc;

use glam::{Quat, Vec3};

use crate::aabb::Aabb;
use crate::body_handle::BodyHandle;
use crate::collider::{Collider, NO_PROXY};
use crate::collision_groups::CollisionGroups;
use crate::combine_rule::CombineRule;
use crate::material::Material;
use crate::pose::Pose;
use crate::shape::{
    Capsule, ConvexHull, Cuboid, HalfSpace, HullError, Shape, Sphere, TriMesh, TriMeshError,
};

/// Default collider density, kg/m³ (water).
pub const DEFAULT_DENSITY: f32 = 1000.0;

/// Builder for a [`Collider`]; pass to [`crate::PhysicsWorld::insert_collider`].
#[derive(Clone, Debug)]
#[must_use]
pub struct ColliderDesc {
    shape: Shape,
    local_pose: Pose,
    material: Material,
    density: f32,
    user_data: u64,
    groups: CollisionGroups,
    sensor: bool,
}

impl ColliderDesc {
    /// Any shape.
    pub fn new(shape: Shape) -> Self {
        Self {
            shape,
            local_pose: Pose::IDENTITY,
            material: Material::default(),
            density: DEFAULT_DENSITY,
            user_data: 0,
            groups: CollisionGroups::ALL,
            sensor: false,
        }
    }

    /// Sphere of radius `r` metres.
    pub fn sphere(r: f32) -> Self {
        Self::new(Shape::Sphere(Sphere { radius: r.max(0.0) }))
    }

    /// Box with half extents in metres.
    pub fn cuboid(hx: f32, hy: f32, hz: f32) -> Self {
        Self::new(Shape::Cuboid(Cuboid {
            half_extents: Vec3::new(hx, hy, hz).max(Vec3::ZERO),
        }))
    }

    /// Capsule along local Y: segment half length and radius, metres.
    pub fn capsule(half_height: f32, radius: f32) -> Self {
        Self::new(Shape::Capsule(Capsule {
            half_height: half_height.max(0.0),
            radius: radius.max(0.0),
        }))
    }

    /// Half space below the plane through the collider origin with outward `normal`
    /// (normalised; a zero normal becomes +Y).
    pub fn half_space(normal: Vec3) -> Self {
        Self::new(Shape::HalfSpace(HalfSpace {
            normal: normal.try_normalize().unwrap_or(Vec3::Y),
        }))
    }

    /// Convex hull of a point cloud.
    ///
    /// # Errors
    /// See [`HullError`].
    pub fn convex_hull(points: &[Vec3]) -> Result<Self, HullError> {
        Ok(Self::new(Shape::ConvexHull(Arc::new(
            ConvexHull::from_points(points)?,
        ))))
    }

    /// Static triangle mesh.
    ///
    /// # Errors
    /// See [`TriMeshError`].
    pub fn trimesh(vertices: Vec<Vec3>, triangles: Vec<[u32; 3]>) -> Result<Self, TriMeshError> {
        Ok(Self::new(Shape::TriMesh(Arc::new(TriMesh::new(
            vertices, triangles,
        )?))))
    }

    /// The same collider with its shape stretched by `scale` ([`Shape::scaled`]: any scale
    /// for boxes, hulls and meshes, the largest component for spheres and capsules). The
    /// pose is left alone: where the shape sits is the caller's. Also returns whether the
    /// scale was non-uniform for a shape that stays round.
    ///
    /// # Errors
    /// A hull or mesh that the scale flattens: the builder's message.
    pub fn scaled(mut self, scale: Vec3) -> Result<(Self, bool), String> {
        let scaled = self.shape.scaled(scale)?;
        self.shape = scaled.shape;
        Ok((self, scaled.made_uniform))
    }

    /// Offset from the body origin, metres.
    pub fn translation(mut self, t: Vec3) -> Self {
        self.local_pose.translation = t;
        self
    }

    /// Rotation relative to the body.
    pub fn rotation(mut self, q: Quat) -> Self {
        self.local_pose.rotation = q.normalize();
        self
    }

    /// Pose relative to the body origin.
    pub fn local_pose(mut self, p: Pose) -> Self {
        self.local_pose = p;
        self
    }

    /// Density, kg/m³ (default [`DEFAULT_DENSITY`]).
    pub fn density(mut self, d: f32) -> Self {
        self.density = d.max(0.0);
        self
    }

    /// Whole material.
    pub fn material(mut self, m: Material) -> Self {
        self.material = m;
        self
    }

    /// Restitution in `[0, 1]`.
    pub fn restitution(mut self, e: f32) -> Self {
        self.material.restitution = e.clamp(0.0, 1.0);
        self
    }

    /// Sets both static and dynamic friction.
    pub fn friction(mut self, mu: f32) -> Self {
        self.material.static_friction = mu.max(0.0);
        self.material.dynamic_friction = mu.max(0.0);
        self
    }

    /// Static friction coefficient.
    pub fn static_friction(mut self, mu: f32) -> Self {
        self.material.static_friction = mu.max(0.0);
        self
    }

    /// Dynamic friction coefficient.
    pub fn dynamic_friction(mut self, mu: f32) -> Self {
        self.material.dynamic_friction = mu.max(0.0);
        self
    }

    /// Friction combine rule.
    pub fn friction_combine(mut self, r: CombineRule) -> Self {
        self.material.friction_combine = r;
        self
    }

    /// Restitution combine rule.
    pub fn restitution_combine(mut self, r: CombineRule) -> Self {
        self.material.restitution_combine = r;
        self
    }

    /// User payload.
    pub fn user_data(mut self, d: u64) -> Self {
        self.user_data = d;
        self
    }

    /// A sensor: overlaps with it are reported as contact events (`ContactEvent::sensor`),
    /// with no contact response, no grounding and no CCD stop; it still has mass from its
    /// density. Overlap is found from the poses a step starts from: the step after the one
    /// that moved a body in (or out) reports it.
    pub fn sensor(mut self, on: bool) -> Self {
        self.sensor = on;
        self
    }

    /// Which groups it is in and collides with (default: all, with all).
    pub fn collision_groups(mut self, groups: CollisionGroups) -> Self {
        self.groups = groups;
        self
    }

    pub(crate) fn build(&self, parent: BodyHandle) -> Collider {
        Collider {
            shape: self.shape.clone(),
            local_pose: self.local_pose,
            parent,
            material: self.material,
            density: self.density,
            user_data: self.user_data,
            groups: self.groups,
            sensor: self.sensor,
            proxy: NO_PROXY,
            aabb: Aabb::new(Vec3::ZERO, Vec3::ZERO),
        }
    }
}
