//! [`WorldSnapshot`]: every entity of the world, with its handle and components, to put back.

use onyx_plugin_api::{Camera, Collider, Light, MeshRenderer, Name, RigidBody, Transform};

use crate::render::previous_transform::PreviousTransform;
use crate::world::PluginComponents;

/// One entity's components.
#[derive(Clone, Debug)]
struct EntityRecord {
    entity: hecs::Entity,
    name: Option<Name>,
    transform: Option<Transform>,
    previous: Option<PreviousTransform>,
    mesh_renderer: Option<MeshRenderer>,
    camera: Option<Camera>,
    light: Option<Light>,
    rigid_body: Option<RigidBody>,
    collider: Option<Collider>,
    plugin: Option<PluginComponents>,
}

/// A copy of the world that [`WorldSnapshot::restore`] puts back with the same entity
/// handles, so references held by plugins and the editor's selection stay valid.
/// Body velocities live in `RigidBody`, so they come back too; physics rebuilds its bodies
/// from the components.
#[derive(Clone, Debug, Default)]
pub struct WorldSnapshot {
    records: Vec<EntityRecord>,
}

fn copy<T: hecs::Component + Clone>(entity: &hecs::EntityRef<'_>) -> Option<T> {
    entity.get::<&T>().map(|v| (*v).clone())
}

impl WorldSnapshot {
    /// Copies every entity of `world`.
    pub fn capture(world: &hecs::World) -> Self {
        let records = world
            .iter()
            .map(|e| EntityRecord {
                entity: e.entity(),
                name: copy(&e),
                transform: copy(&e),
                previous: copy(&e),
                mesh_renderer: copy(&e),
                camera: copy(&e),
                light: copy(&e),
                rigid_body: copy(&e),
                collider: copy(&e),
                plugin: copy(&e),
            })
            .collect();
        Self { records }
    }

    /// Entities held.
    pub fn len(&self) -> usize {
        self.records.len()
    }

    /// Whether it holds no entity.
    pub fn is_empty(&self) -> bool {
        self.records.is_empty()
    }

    /// Replaces everything in `world` with the snapshot, entity handles included.
    pub fn restore(&self, world: &mut hecs::World) {
        world.clear();
        let mut builder = hecs::EntityBuilder::new();
        for r in &self.records {
            if let Some(v) = &r.name {
                builder.add(v.clone());
            }
            if let Some(v) = r.transform {
                builder.add(v);
            }
            if let Some(v) = r.previous {
                builder.add(v);
            }
            if let Some(v) = r.mesh_renderer {
                builder.add(v);
            }
            if let Some(v) = r.camera {
                builder.add(v);
            }
            if let Some(v) = r.light {
                builder.add(v);
            }
            if let Some(v) = r.rigid_body {
                builder.add(v);
            }
            if let Some(v) = r.collider {
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
