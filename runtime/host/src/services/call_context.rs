//! [`CallContext`]: serves one plugin call — the host's implementation of `HostServices`.

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::host::{Blob, HostServices, PhysicsCommand, PluginRequest};
use onyx_plugin_api::{
    BuiltinId, BuiltinValue, Camera, CharacterController, CharacterMove, Collider, ColliderShape,
    Component, CtxError, CustomEvent, DebugLine, Entity, EntityTransform, Event, GlobalTransform,
    InputState, InvalidValue, Joint, KeepPose, LogLevel, MeshId, Parent, QueryFilter, RayHit,
    Script, TextureId, Time, Transform,
};

use crate::entity_id::{to_api, to_hecs};
use crate::state::HostState;
use crate::world::{PluginComponents, StoredBlob, ZeroScaleParent};

/// [`HostState`] lent to one plugin for one call.
pub struct CallContext<'a> {
    pub(super) state: &'a mut HostState,
    pub(super) plugin: &'a str,
}

/// `error` about component `component` of `entity` (`None`: being spawned) as a [`CtxError`].
fn invalid_value(entity: Option<Entity>, component: &str, error: InvalidValue) -> CtxError {
    match error {
        InvalidValue::NonFinite { field } => CtxError::NonFinite {
            entity,
            component: component.to_owned(),
            field: field.to_owned(),
        },
        InvalidValue::Invalid { field, message } => CtxError::InvalidValue {
            entity,
            component: component.to_owned(),
            field: field.to_owned(),
            message,
        },
    }
}

fn missing(entity: Entity, component: &str) -> CtxError {
    CtxError::MissingComponent {
        entity,
        component: component.to_owned(),
    }
}

fn zero_scale(entity: Entity) -> impl FnOnce(ZeroScaleParent) -> CtxError {
    move |_| CtxError::Invalid {
        message: format!(
            "entity {entity} cannot keep its world pose: its parent is scaled to zero"
        ),
    }
}

impl<'a> CallContext<'a> {
    /// Lends `state` to the plugin named `plugin`.
    pub fn new(state: &'a mut HostState, plugin: &'a str) -> Self {
        Self { state, plugin }
    }

    pub(super) fn entity(&self, entity: Entity) -> Result<hecs::Entity, CtxError> {
        self.state
            .world
            .entity(entity)
            .ok_or(CtxError::NoSuchEntity { entity })
    }

    /// Checks a built-in value meant for `entity` (`None`: being spawned) as every write is.
    fn validate(&self, entity: Option<Entity>, value: &BuiltinValue) -> Result<(), CtxError> {
        value
            .validate(&self.state.world.refs())
            .map_err(|e| invalid_value(entity, value.name(), e))?;
        if let (Some(entity), BuiltinValue::Parent(Parent(parent))) = (entity, value) {
            let child = self.entity(entity)?;
            self.state
                .world
                .check_parent(child, *parent)
                .map_err(|problem| CtxError::InvalidParent {
                    entity,
                    parent: *parent,
                    problem,
                })?;
        }
        Ok(())
    }

    /// Checks a plugin component before it is stored (the host's own, `onyx.Script`, must
    /// decode).
    fn validate_blob(blob: &Blob) -> Result<(), CtxError> {
        if blob.name.is_empty() {
            return Err(CtxError::Invalid {
                message: "a plugin component needs a non-empty name".into(),
            });
        }
        if blob.name == Script::NAME {
            serde_json::from_slice::<Script>(&blob.bytes).map_err(|e| CtxError::Decode {
                component: Script::NAME.to_owned(),
                message: e.to_string(),
            })?;
        }
        Ok(())
    }

    fn validate_transforms(&self, items: &[EntityTransform]) -> Result<(), CtxError> {
        for item in items {
            self.entity(item.entity)?;
            self.validate(Some(item.entity), &BuiltinValue::Transform(item.transform))?;
        }
        Ok(())
    }

    /// Writes `items` to the world (checked), telling the scene graph which ones moved.
    fn write_transforms(&mut self, items: &[EntityTransform]) {
        let world = &mut self.state.world;
        // Fast path: `items` is usually the buffer `transforms()` filled from this same query,
        // in the same order; write it back in one pass. Any mismatch falls back to lookups.
        let mut written = 0;
        {
            let query = world.ecs.query_mut::<(hecs::Entity, &mut Transform)>();
            let mut rows = query.into_iter();
            for item in items {
                match rows.next() {
                    Some((e, t)) if to_api(e) == item.entity => {
                        if *t != item.transform {
                            *t = item.transform;
                            world.hierarchy.moved(e);
                        }
                        written += 1;
                    }
                    _ => break,
                }
            }
        }
        for item in &items[written..] {
            let Some(e) = to_hecs(item.entity) else {
                continue;
            };
            world.insert(e, &BuiltinValue::Transform(item.transform));
        }
    }

    fn blobs_of(&self, e: hecs::Entity) -> Vec<Blob> {
        self.state
            .world
            .ecs
            .get::<&PluginComponents>(e)
            .map(|map| {
                map.0
                    .iter()
                    .map(|(name, stored)| Blob {
                        name: name.clone(),
                        format: stored.format,
                        bytes: stored.bytes.clone(),
                    })
                    .collect()
            })
            .unwrap_or_default()
    }

    pub(super) fn components(
        &mut self,
        entity: Entity,
    ) -> Result<(Vec<BuiltinValue>, Vec<Blob>), CtxError> {
        let e = self.entity(entity)?;
        let builtins = crate::world::builtin_storage::all_of(&self.state.world.ecs, e);
        Ok((builtins, self.blobs_of(e)))
    }
}

impl HostServices for CallContext<'_> {
    fn plugin_name(&self) -> &str {
        self.plugin
    }

    fn log(&mut self, level: LogLevel, message: &str) {
        let plugin = self.plugin;
        match level {
            LogLevel::Trace => tracing::trace!(target: "onyx::plugin", plugin, "{message}"),
            LogLevel::Debug => tracing::debug!(target: "onyx::plugin", plugin, "{message}"),
            LogLevel::Info => tracing::info!(target: "onyx::plugin", plugin, "{message}"),
            LogLevel::Warn => tracing::warn!(target: "onyx::plugin", plugin, "{message}"),
            LogLevel::Error => tracing::error!(target: "onyx::plugin", plugin, "{message}"),
        }
    }

    fn time(&self) -> Time {
        self.state.clock.time()
    }

    fn input(&self) -> InputState {
        self.state.io.input
    }

    fn request_quit(&mut self) {
        tracing::info!(plugin = self.plugin, "plugin requested quit");
        self.state.io.quit_requested = true;
    }

    fn prevent_close(&mut self) {
        if self.state.io.close_requested && self.state.io.close_kept_by.is_none() {
            tracing::info!(
                plugin = self.plugin,
                "plugin keeps the window open (it has something to ask first)"
            );
            self.state.io.close_kept_by = Some(self.plugin.to_owned());
        }
    }

    fn set_paused(&mut self, paused: bool) {
        self.state.clock.set_paused(paused);
    }

    fn set_time_scale(&mut self, scale: f32) -> Result<(), CtxError> {
        if self.state.clock.set_time_scale(scale) {
            Ok(())
        } else {
            Err(CtxError::Invalid {
                message: format!("time scale must be finite and ≥ 0, got {scale}"),
            })
        }
    }

    fn step_once(&mut self) {
        self.state.clock.step_once();
    }

    fn spawn(&mut self, builtins: Vec<BuiltinValue>, blobs: Vec<Blob>) -> Result<Entity, CtxError> {
        for value in &builtins {
            self.validate(None, value)?;
        }
        let mut plugin = PluginComponents::default();
        for blob in blobs {
            Self::validate_blob(&blob)?;
            plugin.0.insert(
                blob.name,
                StoredBlob {
                    format: blob.format,
                    bytes: blob.bytes,
                },
            );
        }
        Ok(to_api(self.state.world.spawn(&builtins, plugin)))
    }

    fn despawn(&mut self, entity: Entity) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        self.state.world.despawn(e);
        Ok(())
    }

    fn despawn_recursive(&mut self, entity: Entity) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        self.state.world.despawn_recursive(e);
        Ok(())
    }

    fn contains(&self, entity: Entity) -> bool {
        self.entity(entity).is_ok()
    }

    fn set_parent(
        &mut self,
        entity: Entity,
        parent: Option<Entity>,
        keep: KeepPose,
    ) -> Result<(), CtxError> {
        let child = self.entity(entity)?;
        let parent = match parent {
            Some(parent) => Some(self.state.world.check_parent(child, parent).map_err(
                |problem| CtxError::InvalidParent {
                    entity,
                    parent,
                    problem,
                },
            )?),
            None => None,
        };
        self.state
            .world
            .set_parent(child, parent, keep)
            .map_err(zero_scale(entity))
    }

    fn children(&mut self, entity: Entity) -> Result<Vec<Entity>, CtxError> {
        let e = self.entity(entity)?;
        Ok(self
            .state
            .world
            .children(e)
            .into_iter()
            .map(to_api)
            .collect())
    }

    fn world_pose(&mut self, entity: Entity) -> Result<GlobalTransform, CtxError> {
        let e = self.entity(entity)?;
        Ok(GlobalTransform(self.state.world.world_pose(e)))
    }

    fn set_world_pose(&mut self, entity: Entity, pose: Transform) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        self.validate(Some(entity), &BuiltinValue::Transform(pose))?;
        self.state
            .world
            .set_world_pose(e, &pose)
            .map_err(zero_scale(entity))
    }

    fn get_builtin(&mut self, entity: Entity, id: BuiltinId) -> Result<BuiltinValue, CtxError> {
        let e = self.entity(entity)?;
        self.state
            .world
            .get(e, id)
            .ok_or_else(|| missing(entity, id.name()))
    }

    fn set_builtin(&mut self, entity: Entity, value: BuiltinValue) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        self.validate(Some(entity), &value)?;
        self.state.world.insert(e, &value);
        Ok(())
    }

    fn remove_builtin(&mut self, entity: Entity, id: BuiltinId) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        if self.state.world.remove(e, id) {
            Ok(())
        } else {
            Err(missing(entity, id.name()))
        }
    }

    fn get_blob(&mut self, entity: Entity, name: &str) -> Result<Blob, CtxError> {
        let e = self.entity(entity)?;
        let map = self
            .state
            .world
            .ecs
            .get::<&PluginComponents>(e)
            .map_err(|_| missing(entity, name))?;
        let stored = map.0.get(name).ok_or_else(|| missing(entity, name))?;
        Ok(Blob {
            name: name.to_owned(),
            format: stored.format,
            bytes: stored.bytes.clone(),
        })
    }

    fn set_blob(&mut self, entity: Entity, blob: Blob) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        Self::validate_blob(&blob)?;
        let stored = StoredBlob {
            format: blob.format,
            bytes: blob.bytes,
        };
        let ecs = &mut self.state.world.ecs;
        if let Ok(mut map) = ecs.get::<&mut PluginComponents>(e) {
            map.0.insert(blob.name, stored);
            return Ok(());
        }
        let mut map = PluginComponents::default();
        map.0.insert(blob.name, stored);
        let _ = ecs.insert_one(e, map);
        Ok(())
    }

    fn remove_blob(&mut self, entity: Entity, name: &str) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        let mut map = self
            .state
            .world
            .ecs
            .get::<&mut PluginComponents>(e)
            .map_err(|_| missing(entity, name))?;
        map.0
            .remove(name)
            .map(|_| ())
            .ok_or_else(|| missing(entity, name))
    }

    fn query_blobs(&mut self, name: &str) -> Vec<(Entity, Blob)> {
        let mut rows: Vec<(Entity, Blob)> = self
            .state
            .world
            .ecs
            .query::<(hecs::Entity, &PluginComponents)>()
            .iter()
            .filter_map(|(e, map)| {
                map.0.get(name).map(|stored| {
                    let blob = Blob {
                        name: name.to_owned(),
                        format: stored.format,
                        bytes: stored.bytes.clone(),
                    };
                    (to_api(e), blob)
                })
            })
            .collect();
        rows.sort_by_key(|(e, _)| *e);
        rows
    }

    fn entities(&mut self) -> &[Entity] {
        let state = &mut *self.state;
        let buffer = &mut state.buffers.entities;
        buffer.clear();
        buffer.extend(state.world.ecs.iter().map(|e| to_api(e.entity())));
        buffer
    }

    fn transforms(&mut self) -> &mut [EntityTransform] {
        let state = &mut *self.state;
        let buffer = &mut state.buffers.transforms;
        buffer.clear();
        buffer.extend(
            state
                .world
                .ecs
                .query_mut::<(hecs::Entity, &Transform)>()
                .into_iter()
                .map(|(e, t)| EntityTransform {
                    entity: to_api(e),
                    transform: *t,
                }),
        );
        buffer
    }

    fn commit_transforms(&mut self) -> Result<(), CtxError> {
        let items = std::mem::take(&mut self.state.buffers.transforms);
        let result = self.validate_transforms(&items);
        if result.is_ok() {
            self.write_transforms(&items);
        }
        self.state.buffers.transforms = items;
        result
    }

    fn set_transforms(&mut self, items: &[EntityTransform]) -> Result<(), CtxError> {
        self.validate_transforms(items)?;
        self.write_transforms(items);
        Ok(())
    }

    fn send(&mut self, name: &str, payload: &[u8]) {
        if !self.state.io.count_sent(self.plugin) {
            return;
        }
        self.state.io.events.push(Event::Custom(CustomEvent {
            name: name.to_owned(),
            sender: self.plugin.to_owned(),
            payload: payload.to_vec(),
        }));
    }

    fn request_plugin(&mut self, request: PluginRequest) {
        tracing::debug!(plugin = self.plugin, ?request, "plugin change requested");
        self.state.io.plugin_requests.push(request);
    }

    fn load_mesh(&mut self, path: &str) -> Result<MeshId, CtxError> {
        if path.is_empty() {
            return Err(CtxError::Invalid {
                message: "load_mesh needs a file path".into(),
            });
        }
        Ok(self.state.world.assets.mesh(std::path::Path::new(path)))
    }

    fn load_texture(&mut self, path: &str) -> Result<TextureId, CtxError> {
        if path.is_empty() {
            return Err(CtxError::Invalid {
                message: "load_texture needs a file path".into(),
            });
        }
        Ok(self.state.world.assets.texture(std::path::Path::new(path)))
    }

    fn set_camera(&mut self, entity: Entity) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        if !self.state.world.ecs.satisfies::<&Camera>(e) {
            return Err(missing(entity, "Camera"));
        }
        self.state.view.camera_override = Some(entity);
        Ok(())
    }

    fn draw_debug_lines(&mut self, lines: &[DebugLine]) {
        self.state.io.debug_lines.extend(
            lines
                .iter()
                .filter(|l| l.start.is_finite() && l.end.is_finite()),
        );
    }

    fn physics_command(&mut self, entity: Entity, command: PhysicsCommand) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        if !self.state.world.ecs.satisfies::<&Collider>(e) {
            return Err(missing(entity, "Collider"));
        }
        self.state
            .physics
            .command(entity, command)
            .map_err(|message| CtxError::Invalid { message })
    }

    fn raycast(&mut self, origin: Vec3, direction: Vec3, max_distance: f32) -> Option<RayHit> {
        self.state.physics.raycast(origin, direction, max_distance)
    }

    fn overlap(
        &mut self,
        shape: ColliderShape,
        pose: Transform,
        filter: QueryFilter,
    ) -> Result<Vec<Entity>, CtxError> {
        self.state
            .physics
            .overlap(shape, &pose, &filter)
            .map_err(|message| CtxError::Invalid { message })
    }

    fn shape_cast(
        &mut self,
        shape: ColliderShape,
        pose: Transform,
        direction: Vec3,
        max_distance: f32,
        filter: QueryFilter,
    ) -> Result<Option<RayHit>, CtxError> {
        self.state
            .physics
            .shape_cast(shape, &pose, direction, max_distance, &filter)
            .map_err(|message| CtxError::Invalid { message })
    }

    fn joint_coordinate(&mut self, entity: Entity) -> Result<Option<f32>, CtxError> {
        let e = self.entity(entity)?;
        if !self.state.world.ecs.satisfies::<&Joint>(e) {
            return Err(missing(entity, "Joint"));
        }
        Ok(self.state.physics.joint_coordinate(e))
    }

    fn move_character(
        &mut self,
        entity: Entity,
        desired: Vec3,
        controller: &CharacterController,
    ) -> Result<CharacterMove, CtxError> {
        self.entity(entity)?;
        self.state
            .physics
            .move_character(&mut self.state.world, entity, desired, controller)
            .map_err(|message| CtxError::Invalid { message })
    }
}
