//! [`Collider`]: the shape an entity collides with.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

use super::builtin::{finite, FileRefs, HostRefs};
use crate::{Builtin, InvalidValue, MeshId};

/// A collision shape, in the entity's local frame, scaled with the entity (its world scale:
/// any scale for boxes, hulls and meshes; spheres and capsules stay round and take the
/// largest component, with a warning naming the entity when the scale is not uniform).
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

/// What an entity collides with, and its material. A collider on an entity without a
/// [`RigidBody`](crate::RigidBody) belongs to the nearest ancestor's body (a compound: mass,
/// centre of mass and inertia of all its colliders combined), or is a static body of its own
/// when no ancestor has one. Friction uses the geometric mean of the
/// two colliders; restitution the larger of the two.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Collider {
    /// The shape.
    pub shape: ColliderShape,
    /// Offset of the shape from the entity's origin, local frame, metres (scaled with it).
    pub offset: [f32; 3],
    /// Density, kg/m³ (gives mass and inertia when the body's mass is 0).
    pub density: f32,
    /// Bounciness, 0 (none) to 1 (perfectly elastic).
    pub restitution: f32,
    /// Friction coefficient while sliding.
    pub friction: f32,
    /// Friction coefficient at rest (≥ `friction` in real materials).
    pub static_friction: f32,
    /// The collision groups (bits of 32) this collider is in (default: all).
    pub memberships: u32,
    /// The groups it collides with (default: all). Two colliders collide only when each
    /// one's `memberships` meet the other's `filter`, so either side can refuse: bullets in
    /// group 2 with `filter: !1` fly through their shooter in group 1.
    pub filter: u32,
    /// A sensor (trigger zone): overlaps are reported as
    /// [`PhysicsEvent::SensorEntered`](crate::PhysicsEvent::SensorEntered) / `SensorExited`,
    /// nothing is pushed.
    pub sensor: bool,
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
            memberships: u32::MAX,
            filter: u32::MAX,
            sensor: false,
        }
    }

    /// Returns this collider as a sensor (`true`) or a solid one.
    #[must_use]
    pub const fn with_sensor(mut self, sensor: bool) -> Self {
        self.sensor = sensor;
        self
    }

    /// Returns this collider in groups `memberships`, colliding with `filter`.
    #[must_use]
    pub const fn with_groups(mut self, memberships: u32, filter: u32) -> Self {
        self.memberships = memberships;
        self.filter = filter;
        self
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
}

/// A [`Collider`] as scene files and state dumps write it: mesh shapes by model file path.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ColliderFile {
    /// The shape.
    pub shape: ColliderShapeFile,
    /// Offset from the entity's origin, local frame, metres.
    #[serde(default)]
    pub offset: [f32; 3],
    /// kg/m³.
    #[serde(default = "water")]
    pub density: f32,
    /// Bounciness 0..1.
    #[serde(default)]
    pub restitution: f32,
    /// Sliding friction.
    #[serde(default = "half")]
    pub friction: f32,
    /// Friction at rest (defaults to `friction`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub static_friction: Option<f32>,
    /// Collision groups it is in (default: all).
    #[serde(default = "all_groups", skip_serializing_if = "is_all")]
    pub memberships: u32,
    /// Collision groups it collides with (default: all).
    #[serde(default = "all_groups", skip_serializing_if = "is_all")]
    pub filter: u32,
    /// A sensor: overlaps reported, nothing pushed.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub sensor: bool,
}

fn all_groups() -> u32 {
    u32::MAX
}

fn is_all(groups: &u32) -> bool {
    *groups == u32::MAX
}

fn water() -> f32 {
    1000.0
}

fn half() -> f32 {
    0.5
}

/// A [`ColliderShape`] as scene files write it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum ColliderShapeFile {
    /// Sphere of `radius` m.
    Sphere {
        /// Radius.
        radius: f32,
    },
    /// Box with half extents.
    Box {
        /// Half extents.
        half_extents: [f32; 3],
    },
    /// Capsule along Y.
    Capsule {
        /// Half length of the straight part.
        half_height: f32,
        /// Radius.
        radius: f32,
    },
    /// Half space below the local XZ plane.
    Plane,
    /// Convex hull of a model file's vertices.
    ConvexHull {
        /// Model file.
        mesh: String,
    },
    /// Triangles of a model file (static).
    TriMesh {
        /// Model file.
        mesh: String,
    },
}

fn positive(field: &'static str, value: f32) -> Result<(), InvalidValue> {
    finite(field, &[value])?;
    if value > 0.0 {
        Ok(())
    } else {
        Err(InvalidValue::invalid(
            field,
            format!("must be > 0 m, got {value}"),
        ))
    }
}

fn not_negative(field: &'static str, value: f32) -> Result<(), InvalidValue> {
    finite(field, &[value])?;
    if value >= 0.0 {
        Ok(())
    } else {
        Err(InvalidValue::invalid(
            field,
            format!("must be ≥ 0, got {value}"),
        ))
    }
}

impl Builtin for Collider {
    const NAME: &'static str = "Collider";
    type File = ColliderFile;

    fn tool_default() -> Option<Self> {
        Some(Collider::cuboid(0.5, 0.5, 0.5))
    }

    fn validate(&self, refs: &dyn HostRefs) -> Result<(), InvalidValue> {
        match self.shape {
            ColliderShape::Sphere { radius } => positive("shape.radius", radius)?,
            ColliderShape::Box { half_extents } => {
                for h in half_extents {
                    positive("shape.half_extents", h)?;
                }
            }
            ColliderShape::Capsule {
                half_height,
                radius,
            } => {
                not_negative("shape.half_height", half_height)?;
                positive("shape.radius", radius)?;
            }
            ColliderShape::Plane => {}
            ColliderShape::ConvexHull { mesh } | ColliderShape::TriMesh { mesh } => {
                if refs.mesh_file(mesh).is_none() {
                    return Err(InvalidValue::invalid(
                        "shape.mesh",
                        format!("must be a model from load_mesh, not mesh id {}", mesh.0),
                    ));
                }
            }
        }
        finite("offset", &self.offset)?;
        not_negative("density", self.density)?;
        not_negative("restitution", self.restitution)?;
        not_negative("friction", self.friction)?;
        not_negative("static_friction", self.static_friction)
    }

    fn to_file(&self, refs: &dyn HostRefs) -> ColliderFile {
        let path = |mesh| refs.mesh_file(mesh).unwrap_or_default();
        let shape = match self.shape {
            ColliderShape::Sphere { radius } => ColliderShapeFile::Sphere { radius },
            ColliderShape::Box { half_extents } => ColliderShapeFile::Box { half_extents },
            ColliderShape::Capsule {
                half_height,
                radius,
            } => ColliderShapeFile::Capsule {
                half_height,
                radius,
            },
            ColliderShape::Plane => ColliderShapeFile::Plane,
            ColliderShape::ConvexHull { mesh } => {
                ColliderShapeFile::ConvexHull { mesh: path(mesh) }
            }
            ColliderShape::TriMesh { mesh } => ColliderShapeFile::TriMesh { mesh: path(mesh) },
        };
        ColliderFile {
            shape,
            offset: self.offset,
            density: self.density,
            restitution: self.restitution,
            friction: self.friction,
            static_friction: (self.static_friction != self.friction)
                .then_some(self.static_friction),
            memberships: self.memberships,
            filter: self.filter,
            sensor: self.sensor,
        }
    }

    fn from_file(file: ColliderFile, refs: &mut dyn FileRefs) -> Result<Self, InvalidValue> {
        let shape = match file.shape {
            ColliderShapeFile::Sphere { radius } => ColliderShape::Sphere { radius },
            ColliderShapeFile::Box { half_extents } => ColliderShape::Box { half_extents },
            ColliderShapeFile::Capsule {
                half_height,
                radius,
            } => ColliderShape::Capsule {
                half_height,
                radius,
            },
            ColliderShapeFile::Plane => ColliderShape::Plane,
            ColliderShapeFile::ConvexHull { mesh } => ColliderShape::ConvexHull {
                mesh: refs.mesh(&mesh),
            },
            ColliderShapeFile::TriMesh { mesh } => ColliderShape::TriMesh {
                mesh: refs.mesh(&mesh),
            },
        };
        Ok(Collider {
            shape,
            offset: file.offset,
            density: file.density,
            restitution: file.restitution,
            friction: file.friction,
            static_friction: file.static_friction.unwrap_or(file.friction),
            memberships: file.memberships,
            filter: file.filter,
            sensor: file.sensor,
        })
    }
}
