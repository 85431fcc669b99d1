//! [`pick`]: the nearest entity a ray meets, by what it shows — meshes and colliders at their
//! world poses, without physics (so it works in Edit mode) — and [`local_bounds`], the box
//! around what one entity shows.

use onyx_physics::shape::{Capsule, Cuboid, HalfSpace, Shape, Sphere};
use onyx_plugin_api::glam::{Affine3A, Vec3};
use onyx_plugin_api::tools::Bounds;
use onyx_plugin_api::{Collider, ColliderShape, MeshRenderer, RayHit};

use super::mesh_bounds::MeshBounds;
use crate::entity_id::to_api;
use crate::world::WorldState;

/// A shape to test, in the frame `to_world` maps to world space.
struct Candidate {
    shape: Shape,
    to_world: Affine3A,
}

/// The collider's shape in its own frame (offset applied by the caller), and whether it has
/// no edge: a half space goes on for ever.
fn collider_shape(
    collider: &Collider,
    mesh_bounds: &mut MeshBounds,
    world: &WorldState,
) -> Option<(Shape, Vec3)> {
    let shape = match collider.shape {
        ColliderShape::Sphere { radius } => Shape::Sphere(Sphere { radius }),
        ColliderShape::Box { half_extents } => Shape::Cuboid(Cuboid {
            half_extents: Vec3::from(half_extents),
        }),
        ColliderShape::Capsule {
            half_height,
            radius,
        } => Shape::Capsule(Capsule {
            half_height,
            radius,
        }),
        ColliderShape::Plane => Shape::HalfSpace(HalfSpace { normal: Vec3::Y }),
        // Hulls and triangle meshes by the box of their model.
        ColliderShape::ConvexHull { mesh } | ColliderShape::TriMesh { mesh } => {
            let shape = mesh_bounds.shape(&world.assets, mesh)?;
            return Some((shape.shape.clone(), shape.centre));
        }
    };
    Some((shape, Vec3::ZERO))
}

/// What `e` shows, as shapes to test: its visible mesh at its world pose, and its collider
/// as physics builds it (scaled with the entity). A half-space collider counts only on an entity without a mesh (the
/// mesh shows the part of the ground that is meant: the sky above a floor picks nothing).
fn candidates(world: &WorldState, mesh_bounds: &mut MeshBounds, e: hecs::Entity) -> Vec<Candidate> {
    let mut out = Vec::new();
    let pose = world.world_pose(e);
    let mesh = world
        .ecs
        .get::<&MeshRenderer>(e)
        .ok()
        .filter(|m| m.visible)
        .map(|m| m.mesh);
    if let Some(shape) = mesh.and_then(|m| mesh_bounds.shape(&world.assets, m)) {
        out.push(Candidate {
            shape: shape.shape.clone(),
            to_world: pose * Affine3A::from_translation(shape.centre),
        });
    }
    let collider = world.ecs.get::<&Collider>(e).ok().map(|c| *c);
    if let Some(collider) = collider {
        if let Some((shape, centre)) = collider_shape(&collider, mesh_bounds, world) {
            let unbounded = matches!(shape, Shape::HalfSpace(_));
            if !(unbounded && mesh.is_some()) {
                let offset = Vec3::from(collider.offset) + centre;
                // Colliders scale with their entity, as physics builds them.
                out.push(Candidate {
                    shape,
                    to_world: pose * Affine3A::from_translation(offset),
                });
            }
        }
    }
    out
}

/// Where the ray `origin + t · direction` first meets `candidate`, as `(t, normal)`.
fn cast(candidate: &Candidate, origin: Vec3, direction: Vec3, max: f32) -> Option<(f32, Vec3)> {
    let to_local = candidate.to_world.inverse();
    if !to_local.is_finite() {
        return None; // a zero scale: nothing to hit
    }
    // The same parameter `t` runs along the ray in both frames (the map is affine).
    let o = to_local.transform_point3(origin);
    let d = to_local.transform_vector3(direction);
    let (t, normal) = candidate.shape.cast_local_ray(o, d, max)?;
    // Normals map by the inverse transpose.
    let normal = to_local.matrix3.transpose() * normal;
    Some((t, normal.normalize_or(-direction)))
}

/// The nearest entity whose visible mesh (a built-in shape exactly, a loaded model by its
/// box) or collider the ray from `origin` along `direction` meets within `max_distance`,
/// at world poses. `None` for a ray that meets nothing, or a direction that is not finite
/// or zero.
pub fn pick(
    world: &WorldState,
    mesh_bounds: &mut MeshBounds,
    origin: Vec3,
    direction: Vec3,
    max_distance: f32,
) -> Option<RayHit> {
    let length = direction.length();
    if !(origin.is_finite() && length.is_finite() && length > 0.0 && max_distance >= 0.0) {
        return None;
    }
    let direction = direction / length;
    let shown: Vec<hecs::Entity> = world
        .ecs
        .query::<(hecs::Entity, hecs::Or<&MeshRenderer, &Collider>)>()
        .iter()
        .map(|(e, _)| e)
        .collect();
    let mut best: Option<RayHit> = None;
    for e in shown {
        for candidate in candidates(world, mesh_bounds, e) {
            let Some((t, normal)) = cast(&candidate, origin, direction, max_distance) else {
                continue;
            };
            if best.as_ref().is_none_or(|b| t < b.distance) {
                best = Some(RayHit {
                    entity: to_api(e),
                    point: origin + direction * t,
                    normal,
                    distance: t,
                });
            }
        }
    }
    best
}

/// The box around what `e` shows in its own frame: its visible mesh, else its collider
/// (a half space: the unit square it stands for). `None` for an entity showing neither.
pub fn local_bounds(
    world: &WorldState,
    mesh_bounds: &mut MeshBounds,
    e: hecs::Entity,
) -> Option<Bounds> {
    let mesh = world
        .ecs
        .get::<&MeshRenderer>(e)
        .ok()
        .filter(|m| m.visible)
        .map(|m| m.mesh);
    if let Some(shape) = mesh.and_then(|m| mesh_bounds.shape(&world.assets, m)) {
        return Some(shape.bounds);
    }
    let collider = world.ecs.get::<&Collider>(e).ok().map(|c| *c)?;
    let (shape, centre) = collider_shape(&collider, mesh_bounds, world)?;
    let half = match shape {
        Shape::Sphere(s) => Vec3::splat(s.radius),
        Shape::Cuboid(c) => c.half_extents,
        Shape::Capsule(c) => Vec3::new(c.radius, c.half_height + c.radius, c.radius),
        Shape::HalfSpace(_) => Vec3::new(0.5, 0.0, 0.5),
        Shape::ConvexHull(_) | Shape::TriMesh(_) => return None,
    };
    // The collider scales with its entity, so its box in the entity's frame is its own.
    let middle = Vec3::from(collider.offset) + centre;
    Some(Bounds {
        min: middle - half,
        max: middle + half,
    })
}
