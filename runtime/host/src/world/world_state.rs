//! [`WorldState`]: the entities and their components, the scene graph over them and the
//! assets they name — the part of the host every system reads, written through methods that
//! keep the scene graph in step.

use onyx_plugin_api::glam::Affine3A;
use onyx_plugin_api::{
    BuiltinId, BuiltinValue, Entity, KeepPose, Parent, ParentProblem, Transform,
};

use super::builtin_storage;
use super::{PluginComponents, WorldRefs};
use crate::assets::AssetRegistry;
use crate::entity_id::{to_api, to_hecs};
use crate::hierarchy::world_pose::{self, local_for};
use crate::hierarchy::TransformHierarchy;

/// The world: hecs entities holding the built-in components (each as its own type) and
/// [`PluginComponents`], the [`TransformHierarchy`] over their [`Parent`]s, and the
/// [`AssetRegistry`] their meshes and textures come from.
///
/// Reads go straight to `ecs`. Writes of a `Transform` or a `Parent` go through
/// [`WorldState::insert`] and friends (or are reported with [`WorldState::moved`]), so the
/// scene graph knows which world poses to recompute; code that edits `ecs` any other way
/// calls [`TransformHierarchy::invalidate`].
#[derive(Default)]
pub struct WorldState {
    /// The entities and their components.
    pub ecs: hecs::World,
    /// Parents, children and world poses.
    pub hierarchy: TransformHierarchy,
    /// Mesh and texture ids ↔ files.
    pub assets: AssetRegistry,
}

impl std::fmt::Debug for WorldState {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("WorldState")
            .field("entities", &self.ecs.len())
            .field("in_hierarchy", &self.hierarchy.len())
            .finish()
    }
}

/// Why an entity could not be kept where it is in the world while changing parent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ZeroScaleParent;

impl WorldState {
    /// An empty world whose assets resolve against `assets`' root.
    pub fn new(assets: AssetRegistry) -> Self {
        Self {
            ecs: hecs::World::new(),
            hierarchy: TransformHierarchy::new(),
            assets,
        }
    }

    /// The hecs entity of `entity`, if it exists.
    pub fn entity(&self, entity: Entity) -> Option<hecs::Entity> {
        to_hecs(entity).filter(|e| self.ecs.contains(*e))
    }

    /// Lookups for component checks and dumps (entities named by their handle's bits).
    pub fn refs(&self) -> WorldRefs<'_> {
        WorldRefs {
            ecs: &self.ecs,
            assets: &self.assets,
            file_ids: None,
        }
    }

    /// Every entity, in no particular order.
    pub fn all_entities(&self) -> Vec<hecs::Entity> {
        self.ecs.iter().map(|e| e.entity()).collect()
    }

    /// Despawns `entities` (all there were, for a new or opened scene). The world goes on
    /// handing out handles after theirs: a fresh `hecs::World` would start over, and a handle
    /// kept from before would name a newcomer (the editor's camera handle from an empty scene
    /// named the first entity of the next scene opened, and moved it with the view).
    pub fn despawn_all_of(&mut self, entities: &[hecs::Entity]) {
        for &e in entities {
            let _ = self.ecs.despawn(e);
        }
        self.hierarchy.invalidate();
    }

    /// Brings the scene graph's world poses up to date (changed subtrees only).
    pub fn propagate(&mut self) {
        self.hierarchy.propagate(&self.ecs);
    }

    /// Tells the scene graph that the `Transform` of `e` was written in place.
    pub fn moved(&mut self, e: hecs::Entity) {
        self.hierarchy.moved(e);
    }

    /// A new entity with these components (already checked; a `Parent` among them names an
    /// existing entity).
    pub fn spawn(&mut self, builtins: &[BuiltinValue], plugin: PluginComponents) -> hecs::Entity {
        let mut builder = hecs::EntityBuilder::new();
        for value in builtins {
            builtin_storage::add_to(&mut builder, value);
        }
        if !plugin.0.is_empty() {
            builder.add(plugin);
        }
        let e = self.ecs.spawn(builder.build());
        for value in builtins {
            self.written(e, value);
        }
        e
    }

    /// Inserts or replaces a built-in of `e` (which exists; the value was checked, and a
    /// `Parent` makes no cycle).
    pub fn insert(&mut self, e: hecs::Entity, value: &BuiltinValue) {
        builtin_storage::insert(&mut self.ecs, e, value);
        self.written(e, value);
    }

    /// Tells the scene graph that `value` was written to `e`.
    fn written(&mut self, e: hecs::Entity, value: &BuiltinValue) {
        match value {
            BuiltinValue::Transform(_) => self.hierarchy.moved(e),
            BuiltinValue::Parent(Parent(parent)) => match to_hecs(*parent) {
                Some(parent) => self.hierarchy.attach(e, parent),
                None => self.hierarchy.invalidate(),
            },
            _ => {}
        }
    }

    /// The built-in `id` of `e`.
    pub fn get(&self, e: hecs::Entity, id: BuiltinId) -> Option<BuiltinValue> {
        builtin_storage::get(&self.ecs, e, id)
    }

    /// Removes the built-in `id` of `e`; whether it had one.
    pub fn remove(&mut self, e: hecs::Entity, id: BuiltinId) -> bool {
        let removed = builtin_storage::remove(&mut self.ecs, e, id);
        match id {
            BuiltinId::Transform if removed => self.hierarchy.moved(e),
            BuiltinId::Parent if removed => self.hierarchy.detach(e),
            _ => {}
        }
        removed
    }

    /// Checks that `parent` can be the parent of `child`: it exists, is not `child`, and is
    /// not below it.
    pub fn check_parent(
        &self,
        child: hecs::Entity,
        parent: Entity,
    ) -> Result<hecs::Entity, ParentProblem> {
        let parent = self.entity(parent).ok_or(ParentProblem::Missing)?;
        if parent == child {
            return Err(ParentProblem::Itself);
        }
        if world_pose::is_ancestor_or_self(&self.ecs, child, parent) {
            return Err(ParentProblem::Descendant);
        }
        Ok(parent)
    }

    /// Puts `child` under `parent` (checked with [`WorldState::check_parent`]) or makes it a
    /// root, keeping its world pose or its local transform.
    pub fn set_parent(
        &mut self,
        child: hecs::Entity,
        parent: Option<hecs::Entity>,
        keep: KeepPose,
    ) -> Result<(), ZeroScaleParent> {
        let local = match keep {
            KeepPose::Local => None,
            KeepPose::World => {
                let world = world_pose::world_pose_now(&self.ecs, child);
                let parent_world = parent.map_or(Affine3A::IDENTITY, |p| {
                    world_pose::world_pose_now(&self.ecs, p)
                });
                Some(local_for(parent_world, world).ok_or(ZeroScaleParent)?)
            }
        };
        match parent {
            Some(p) => self.insert(child, &BuiltinValue::Parent(Parent(to_api(p)))),
            None => {
                self.remove(child, BuiltinId::Parent);
            }
        }
        if let Some(local) = local {
            let had = self.ecs.satisfies::<&Transform>(child);
            if had || !approx_identity(&local) {
                self.insert(child, &BuiltinValue::Transform(local));
            }
        }
        Ok(())
    }

    /// Moves `e` to `pose` in the world by writing the local transform that puts it there.
    pub fn set_world_pose(
        &mut self,
        e: hecs::Entity,
        pose: &Transform,
    ) -> Result<(), ZeroScaleParent> {
        let parent_world = world_pose::parent_world_now(&self.ecs, e);
        let local = local_for(parent_world, pose.affine()).ok_or(ZeroScaleParent)?;
        self.insert(e, &BuiltinValue::Transform(local));
        Ok(())
    }

    /// The world pose of `e`, exact after every write so far.
    pub fn world_pose(&self, e: hecs::Entity) -> Affine3A {
        world_pose::world_pose_now(&self.ecs, e)
    }

    /// The children of `e`, in the order they were attached (brings the index up to date
    /// first when it was invalidated).
    pub fn children(&mut self, e: hecs::Entity) -> Vec<hecs::Entity> {
        self.hierarchy.refresh_index(&self.ecs);
        self.hierarchy.children(e).to_vec()
    }

    /// Despawns `e`. Its children become roots and stay where they are in the world.
    pub fn despawn(&mut self, e: hecs::Entity) -> bool {
        if !self.ecs.contains(e) {
            return false;
        }
        for child in self.children(e) {
            // A root's world pose is its local one: a zero scale cannot fail here.
            let _ = self.set_parent(child, None, KeepPose::World);
        }
        self.hierarchy.despawned(e);
        self.ecs.despawn(e).is_ok()
    }

    /// Despawns `e` and every entity below it.
    pub fn despawn_recursive(&mut self, e: hecs::Entity) -> bool {
        if !self.ecs.contains(e) {
            return false;
        }
        self.hierarchy.refresh_index(&self.ecs);
        let subtree = self.hierarchy.subtree(e);
        for entity in subtree.into_iter().rev() {
            self.hierarchy.despawned(entity);
            let _ = self.ecs.despawn(entity);
        }
        true
    }
}

fn approx_identity(t: &Transform) -> bool {
    t.translation
        .abs_diff_eq(onyx_plugin_api::glam::Vec3::ZERO, 1e-6)
        && t.rotation
            .abs_diff_eq(onyx_plugin_api::glam::Quat::IDENTITY, 1e-6)
        && t.scale.abs_diff_eq(onyx_plugin_api::glam::Vec3::ONE, 1e-6)
}
