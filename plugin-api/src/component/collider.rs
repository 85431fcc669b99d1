//! [`Collider`]: the shape an entity collides with.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

use crate::MeshId;

/// A collision shape, in the entity's local frame (the transform's scale does not apply).
#[repr(C, u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum ColliderShape {
    /// A sphere of `radius` metres.
    Sphere {
        /// Radius, m.
        radius: f32,
    },
    /// A box with these half extents, metres.
    Box {
        /// Half width, height and depth, m.
        half_extents: [f32; 3],
    },
    /// A capsule along local Y: a cylinder of `half_height` × 2 capped by hemispheres.
    Capsule {
        /// Half the length of the cylinder part, m.
        half_height: f32,
        /// Radius, m.
        radius: f32,
    },
    /// Everything below the entity's local XZ plane (normal = local +Y): ground, walls.
    Plane,
    /// The convex hull of a model's vertices ([`Ctx::load_mesh`](crate::Ctx::load_mesh)).
    ConvexHull {
        /// The model.
        mesh: MeshId,
    },
    /// A model's triangles, as static level geometry.
    TriMesh {
        /// The model.
        mesh: MeshId,
    },
}

/// What an entity collides with, and its material. Friction uses the geometric mean of the
/// two colliders; restitution the larger of the two.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Collider {
    /// The shape.
    pub shape: ColliderShape,
    /// Offset of the shape from the entity's origin, local frame, metres.
    pub offset: [f32; 3],
    /// Density, kg/m³ (gives mass and inertia when the body's mass is 0).
    pub density: f32,
    /// Bounciness, 0 (none) to 1 (perfectly elastic).
    pub restitution: f32,
    /// Friction coefficient while sliding.
    pub friction: f32,
    /// Friction coefficient at rest (≥ `friction` in real materials).
    pub static_friction: f32,
}

impl Collider {
    /// A collider of `shape`: density 1000 kg/m³ (water), friction 0.5, no bounce.
    pub const fn new(shape: ColliderShape) -> Self {
        Self {
            shape,
            offset: [0.0; 3],
            density: 1000.0,
            restitution: 0.0,
            friction: 0.5,
            static_friction: 0.5,
        }
    }

    /// A sphere.
    pub const fn sphere(radius: f32) -> Self {
        Self::new(ColliderShape::Sphere { radius })
    }

    /// A box with half extents (hx, hy, hz).
    pub const fn cuboid(hx: f32, hy: f32, hz: f32) -> Self {
        Self::new(ColliderShape::Box {
            half_extents: [hx, hy, hz],
        })
    }

    /// A capsule along Y.
    pub const fn capsule(half_height: f32, radius: f32) -> Self {
        Self::new(ColliderShape::Capsule {
            half_height,
            radius,
        })
    }

    /// A half space below the entity's local XZ plane.
    pub const fn plane() -> Self {
        Self::new(ColliderShape::Plane)
    }

    /// Returns this collider with restitution `e`.
    #[must_use]
    pub const fn with_restitution(mut self, e: f32) -> Self {
        self.restitution = e;
        self
    }

    /// Returns this collider with friction `mu`, at rest and sliding.
    #[must_use]
    pub const fn with_friction(mut self, mu: f32) -> Self {
        self.friction = mu;
        self.static_friction = mu;
        self
    }

    /// Returns this collider with `density` kg/m³.
    #[must_use]
    pub const fn with_density(mut self, density: f32) -> Self {
        self.density = density;
        self
    }

    /// Whether every number is finite and sizes are positive.
    pub fn is_valid(&self) -> bool {
        let sizes_ok = match self.shape {
            ColliderShape::Sphere { radius } => radius.is_finite() && radius > 0.0,
            ColliderShape::Box { half_extents } => {
                half_extents.iter().all(|h| h.is_finite() && *h > 0.0)
            }
            ColliderShape::Capsule {
                half_height,
                radius,
            } => {
                half_height.is_finite() && half_height >= 0.0 && radius.is_finite() && radius > 0.0
            }
            _ => true,
        };
        sizes_ok
            && self.offset.iter().all(|v| v.is_finite())
            && [
                self.density,
                self.restitution,
                self.friction,
                self.static_friction,
            ]
            .iter()
            .all(|v| v.is_finite() && *v >= 0.0)
    }
}
