//! World poses computed on demand from the world's components, without the cache: exact
//! after any write, for single lookups (`Ctx::world_pose`, re-parenting, dumps).

use onyx_plugin_api::glam::Affine3A;
use onyx_plugin_api::{Parent, Transform};

use crate::entity_id::to_hecs;

/// Most ancestors followed up one chain. The host refuses cycles, so only a world edited
/// past its checks (`Host::world_mut`) can hold a longer chain; it is cut there.
pub const MAX_DEPTH: usize = 4096;

/// The parent of `entity` as its `Parent` component names it, if that entity exists.
pub fn parent_in(world: &hecs::World, entity: hecs::Entity) -> Option<hecs::Entity> {
    let parent = world.get::<&Parent>(entity).ok()?;
    to_hecs(parent.0).filter(|p| world.contains(*p) && *p != entity)
}

/// `entity`, its parent, its grandparent, … up to the root (at most [`MAX_DEPTH`]).
pub fn ancestry(world: &hecs::World, entity: hecs::Entity) -> Vec<hecs::Entity> {
    let mut chain = vec![entity];
    while chain.len() < MAX_DEPTH {
        match parent_in(world, chain[chain.len() - 1]) {
            Some(p) if !chain.contains(&p) => chain.push(p),
            _ => break,
        }
    }
    chain
}

/// Whether `ancestor` is `entity` itself or above it in the scene graph.
pub fn is_ancestor_or_self(
    world: &hecs::World,
    ancestor: hecs::Entity,
    entity: hecs::Entity,
) -> bool {
    ancestry(world, entity).contains(&ancestor)
}

/// The local transform of `entity` as a matrix (identity without a `Transform`).
pub fn local_of(world: &hecs::World, entity: hecs::Entity) -> Affine3A {
    world
        .get::<&Transform>(entity)
        .map_or(Affine3A::IDENTITY, |t| t.affine())
}

/// The world pose of `entity`: its local transform with every ancestor's applied.
pub fn world_pose_now(world: &hecs::World, entity: hecs::Entity) -> Affine3A {
    parent_world_now(world, entity) * local_of(world, entity)
}

/// The world pose of the parent of `entity` (identity for a root).
pub fn parent_world_now(world: &hecs::World, entity: hecs::Entity) -> Affine3A {
    ancestry(world, entity)
        .iter()
        .skip(1)
        .rev()
        .fold(Affine3A::IDENTITY, |acc, e| acc * local_of(world, *e))
}

/// The local transform that puts an entity whose parent is at `parent_world` at `world`
/// (translation, rotation and scale of the nearest unsheared pose); `None` when the parent's
/// pose cannot be inverted (a zero scale).
pub fn local_for(parent_world: Affine3A, world: Affine3A) -> Option<Transform> {
    if parent_world.matrix3.determinant().abs() <= f32::MIN_POSITIVE {
        return None;
    }
    let local = parent_world.inverse() * world;
    let (scale, rotation, translation) = local.to_scale_rotation_translation();
    let local = Transform {
        translation,
        rotation: rotation.normalize(),
        scale,
    };
    local.is_finite().then_some(local)
}
