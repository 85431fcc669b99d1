//! Compound bodies: which body each `Collider` component belongs to — its own entity's
//! `RigidBody`, or else the nearest ancestor's — and where it sits on that body, with the
//! world scale of its entity.
//!
//! A collider with no `RigidBody` on itself or above it is a static body of its own. The
//! placement is computed from the local transforms between the body's entity and the
//! collider's (never from world poses), so it does not change while the body moves and a
//! body is only rebuilt when the scene graph under it changes.

use onyx_physics::glam::{Affine3A, Quat, Vec3};
use onyx_physics::Pose;
use onyx_plugin_api::{Collider, RigidBody, Transform};

use crate::hierarchy::world_pose;

/// Where a collider sits on its body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Placement {
    /// The shape's pose relative to the body's origin (the component's offset included,
    /// scaled with its entity).
    pub pose: Pose,
    /// The scale the shape takes: the product of the scales from the root down to the
    /// collider's entity (a shear from a rotated non-uniform parent is not followed).
    pub scale: Vec3,
}

/// A `Collider` component as its body takes it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct PlacedCollider {
    /// The entity holding the component.
    pub entity: hecs::Entity,
    /// The component.
    pub collider: Collider,
    /// Where it sits on the body.
    pub placement: Placement,
}

/// One body to simulate: the entity it belongs to and every collider on it.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct BodyColliders {
    /// The entity with the `RigidBody` (or, for a static collider of its own, the
    /// collider's entity).
    pub owner: hecs::Entity,
    /// Its colliders, in the order the world holds them.
    pub colliders: Vec<PlacedCollider>,
}

/// Every body the world's colliders make, in a fixed order (the order of the first collider
/// of each in the world's query), so the simulation is the same from run to run.
pub(super) fn gather(ecs: &hecs::World) -> Vec<BodyColliders> {
    let mut bodies: Vec<BodyColliders> = Vec::new();
    let mut index: std::collections::HashMap<hecs::Entity, usize> =
        std::collections::HashMap::new();
    for (e, collider) in ecs.query::<(hecs::Entity, &Collider)>().iter() {
        let (owner, placement) = place(ecs, e, collider);
        let slot = *index.entry(owner).or_insert_with(|| {
            bodies.push(BodyColliders {
                owner,
                colliders: Vec::new(),
            });
            bodies.len() - 1
        });
        bodies[slot].colliders.push(PlacedCollider {
            entity: e,
            collider: *collider,
            placement,
        });
    }
    bodies
}

fn scale_of(ecs: &hecs::World, e: hecs::Entity) -> Vec3 {
    ecs.get::<&Transform>(e).map_or(Vec3::ONE, |t| t.scale)
}

/// The body entity of the collider on `e` and where the collider sits on it.
fn place(ecs: &hecs::World, e: hecs::Entity, collider: &Collider) -> (hecs::Entity, Placement) {
    let offset = Vec3::from(collider.offset);
    // A root (the common case) owns its collider: no chain to walk.
    if world_pose::parent_in(ecs, e).is_none() {
        let scale = scale_of(ecs, e);
        let pose = Pose::new(offset * scale, Quat::IDENTITY);
        return (e, Placement { pose, scale });
    }
    let chain = world_pose::ancestry(ecs, e);
    let owner_at = chain
        .iter()
        .position(|a| ecs.satisfies::<&RigidBody>(*a))
        .unwrap_or(0);
    let owner = chain[owner_at];
    // The owner's world scale: the scales from the root down to it.
    let owner_scale = chain[owner_at..]
        .iter()
        .fold(Vec3::ONE, |s, a| s * scale_of(ecs, *a));
    // The entities below the owner down to the collider's, applied from the top.
    let below = &chain[..owner_at];
    let relative = below
        .iter()
        .rev()
        .fold(Affine3A::from_scale(owner_scale), |acc, a| {
            acc * world_pose::local_of(ecs, *a)
        });
    let scale = below.iter().fold(owner_scale, |s, a| s * scale_of(ecs, *a));
    let rotation = if below.is_empty() {
        Quat::IDENTITY
    } else {
        relative.to_scale_rotation_translation().1.normalize()
    };
    let pose = Pose::new(relative.transform_point3(offset), rotation);
    (owner, Placement { pose, scale })
}

#[cfg(test)]
mod tests {
    use super::*;
    use onyx_plugin_api::{Parent, RigidBody};

    use crate::entity_id::to_api;

    #[test]
    fn a_child_collider_without_a_body_belongs_to_its_ancestors_body() {
        let mut ecs = hecs::World::new();
        let root = ecs.spawn((
            Transform::from_xyz(0.0, 5.0, 0.0).with_scale(Vec3::splat(2.0)),
            RigidBody::dynamic(),
            Collider::cuboid(0.5, 0.5, 0.5),
        ));
        let middle = ecs.spawn((Transform::from_xyz(1.0, 0.0, 0.0), Parent(to_api(root))));
        let leaf = ecs.spawn((
            Transform::from_xyz(0.0, 1.0, 0.0).with_scale(Vec3::new(1.0, 3.0, 1.0)),
            Parent(to_api(middle)),
            Collider::cuboid(0.5, 0.5, 0.5),
        ));
        let loose = ecs.spawn((Transform::IDENTITY, Collider::sphere(1.0)));
        let bodies = gather(&ecs);
        assert_eq!(bodies.len(), 2, "{bodies:?}");
        let body = bodies
            .iter()
            .find(|b| b.owner == root)
            .expect("root's body");
        assert_eq!(body.colliders.len(), 2);
        let own = body.colliders.iter().find(|c| c.entity == root).unwrap();
        assert_eq!(own.placement.scale, Vec3::splat(2.0));
        let child = body.colliders.iter().find(|c| c.entity == leaf).unwrap();
        // (1, 1, 0) under the root's scale of 2.
        assert!(
            child
                .placement
                .pose
                .translation
                .distance(Vec3::new(2.0, 2.0, 0.0))
                < 1e-6,
            "{:?}",
            child.placement
        );
        assert_eq!(child.placement.scale, Vec3::new(2.0, 6.0, 2.0));
        assert!(bodies.iter().any(|b| b.owner == loose));
    }
}
