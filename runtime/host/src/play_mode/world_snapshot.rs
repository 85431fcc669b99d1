//! [`WorldSnapshot`]: every entity of the world, with its handle and components, to put back.

use onyx_plugin_api::BuiltinValue;

use crate::render::PreviousPose;
use crate::world::{builtin_storage, PluginComponents};

/// One entity's components.
#[derive(Clone, Debug)]
struct EntityRecord {
    entity: hecs::Entity,
    builtins: Vec<BuiltinValue>,
    previous: Option<PreviousPose>,
    plugin: Option<PluginComponents>,
}

/// A copy of the world that [`WorldSnapshot::restore`] puts back with the same entity
/// handles, so references held by plugins and the editor's selection stay valid (parents
/// included). Body velocities live in `RigidBody`, so they come back too; physics rebuilds
/// its bodies from the components, and the scene graph its index.
#[derive(Clone, Debug, Default)]
pub struct WorldSnapshot {
    records: Vec<EntityRecord>,
}

impl WorldSnapshot {
    /// Copies every entity of `world`.
    pub fn capture(world: &hecs::World) -> Self {
        let records = world
            .iter()
            .map(|e| EntityRecord {
                entity: e.entity(),
                builtins: builtin_storage::all_of(world, e.entity()),
                previous: e.get::<&PreviousPose>().map(|p| *p),
                plugin: e.get::<&PluginComponents>().map(|p| (*p).clone()),
            })
            .collect();
        Self { records }
    }

    /// Entities held.
    pub fn len(&self) -> usize {
        self.records.len()
    }

    /// Replaces everything in `world` with the snapshot, entity handles included. The
    /// world's scene graph must be told (the caller invalidates it).
    pub fn restore(&self, world: &mut hecs::World) {
        world.clear();
        let mut builder = hecs::EntityBuilder::new();
        for r in &self.records {
            for value in &r.builtins {
                builtin_storage::add_to(&mut builder, value);
            }
            if let Some(v) = r.previous {
                builder.add(v);
            }
            if let Some(v) = &r.plugin {
                builder.add(v.clone());
            }
            world.spawn_at(r.entity, builder.build());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use onyx_plugin_api::{Name, Transform};

    #[test]
    fn restore_brings_back_every_entity_with_its_handle_and_drops_newer_ones() {
        let mut world = hecs::World::new();
        let gone = world.spawn((Name::new("gone"),));
        let kept = world.spawn((Name::new("kept"), Transform::from_xyz(1.0, 2.0, 3.0)));
        world.despawn(gone).unwrap();
        let snapshot = WorldSnapshot::capture(&world);
        world.get::<&mut Transform>(kept).unwrap().translation.x = 9.0;
        let newer = world.spawn((Name::new("newer"),));
        snapshot.restore(&mut world);
        assert_eq!(world.len(), 1);
        assert!(!world.contains(newer) || newer == kept);
        assert_eq!(world.get::<&Name>(kept).unwrap().as_str(), "kept");
        assert_eq!(world.get::<&Transform>(kept).unwrap().translation.x, 1.0);
        // Handles made after a restore do not collide with restored ones.
        let fresh = world.spawn((Name::new("fresh"),));
        assert_ne!(fresh, kept);
        assert_eq!(world.len(), 2);
    }
}
