//! [`CallContext`]: serves one plugin call — the host's implementation of `HostServices`.

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::host::{
    Blob, BuiltinId, BuiltinValue, HostServices, PhysicsCommand, PluginRequest,
};
use onyx_plugin_api::{
    Camera, Collider, CtxError, CustomEvent, DebugLine, Entity, EntityTransform, Event, InputState,
    Light, LogLevel, MeshId, MeshRenderer, Name, RayHit, RigidBody, TextureId, Time, Transform,
};

use super::entity_id::{to_api, to_hecs};
use super::{PluginComponents, StoredBlob};
use crate::clock::FixedClock;
use crate::physics::PhysicsSystem;
use crate::render::{AssetRegistry, OrbitCamera};

/// The parts of the host a plugin call can reach (everything but the plugins themselves).
pub struct HostState {
    /// The entities and their components.
    pub world: hecs::World,
    /// The fixed-step clock.
    pub clock: FixedClock,
    /// Keyboard and mouse state for this frame.
    pub input: InputState,
    /// Events waiting for the next dispatch.
    pub pending_events: Vec<Event>,
    /// Set when a plugin or the window asked to quit.
    pub quit_requested: bool,
    /// Plugin changes asked for during the frame, carried out after it.
    pub plugin_requests: Vec<PluginRequest>,
    /// Mesh and texture ids ↔ files.
    pub assets: AssetRegistry,
    /// Debug lines plugins drew this frame.
    pub debug_lines: Vec<DebugLine>,
    /// The camera entity chosen with `Ctx::set_camera`.
    pub camera_override: Option<Entity>,
    /// The view used when no camera is chosen or active.
    pub orbit: OrbitCamera,
    /// Rigid-body physics.
    pub physics: PhysicsSystem,
    /// What the tool services keep (diagnostics, play mode, scripts, view switches).
    pub tools: super::ToolState,
    entity_buffer: Vec<Entity>,
    transform_buffer: Vec<EntityTransform>,
}

impl HostState {
    /// An empty world with `clock`.
    pub fn new(clock: FixedClock) -> Self {
        Self {
            world: hecs::World::new(),
            clock,
            input: InputState::default(),
            pending_events: Vec::new(),
            quit_requested: false,
            plugin_requests: Vec::new(),
            assets: AssetRegistry::default(),
            debug_lines: Vec::new(),
            camera_override: None,
            orbit: OrbitCamera::default(),
            physics: PhysicsSystem::default(),
            tools: super::ToolState::default(),
            entity_buffer: Vec::new(),
            transform_buffer: Vec::new(),
        }
    }
}

/// [`HostState`] lent to one plugin for one call.
pub struct CallContext<'a> {
    pub(super) state: &'a mut HostState,
    pub(super) plugin: &'a str,
}

impl<'a> CallContext<'a> {
    /// Lends `state` to the plugin named `plugin`.
    pub fn new(state: &'a mut HostState, plugin: &'a str) -> Self {
        Self { state, plugin }
    }

    pub(super) fn entity(&self, entity: Entity) -> Result<hecs::Entity, CtxError> {
        to_hecs(entity)
            .filter(|e| self.state.world.contains(*e))
            .ok_or(CtxError::NoSuchEntity { entity })
    }

    pub(super) fn validate(&self, entity: Entity, value: &BuiltinValue) -> Result<(), CtxError> {
        let non_finite = |component: &str| CtxError::NonFinite {
            entity,
            component: component.into(),
        };
        let invalid = |message: String| Err(CtxError::Invalid { message });
        match value {
            BuiltinValue::Transform(t) if !t.is_finite() => Err(non_finite("Transform")),
            BuiltinValue::MeshRenderer(r) => {
                if !r.material.color.iter().all(|c| c.is_finite()) {
                    return Err(non_finite("MeshRenderer"));
                }
                if !self.state.assets.knows_mesh(r.mesh) {
                    return invalid(format!("mesh id {} was not given by this host", r.mesh.0));
                }
                if !self.state.assets.knows_texture(r.material.texture) {
                    return invalid(format!(
                        "texture id {} was not given by this host",
                        r.material.texture.0
                    ));
                }
                Ok(())
            }
            BuiltinValue::Camera(c) => {
                let extent = match c.projection {
                    onyx_plugin_api::Projection::Perspective { fov_y } => fov_y,
                    onyx_plugin_api::Projection::Orthographic { height } => height,
                };
                if !(c.near.is_finite() && c.far.is_finite() && extent.is_finite()) {
                    return Err(non_finite("Camera"));
                }
                if !(c.near > 0.0 && c.far > c.near && extent > 0.0) {
                    return invalid(format!(
                        "a camera needs 0 < near < far and a positive field of view or height \
                         (near {}, far {}, {extent})",
                        c.near, c.far
                    ));
                }
                Ok(())
            }
            BuiltinValue::Light(l) if !l.is_finite() => Err(non_finite("Light")),
            BuiltinValue::RigidBody(b) if !b.is_finite() => Err(non_finite("RigidBody")),
            BuiltinValue::RigidBody(b) if b.mass < 0.0 => invalid(format!("a body's mass must be ≥ 0, got {}", b.mass)),
            BuiltinValue::Collider(c) if !c.is_valid() => invalid(
                "a collider needs finite values, positive sizes and non-negative density and friction".into(),
            ),
            BuiltinValue::Collider(c) => match c.shape {
                onyx_plugin_api::ColliderShape::ConvexHull { mesh }
                | onyx_plugin_api::ColliderShape::TriMesh { mesh }
                    if self.state.assets.mesh_path(mesh).is_none() =>
                {
                    invalid(format!("a mesh collider needs a model from load_mesh, not mesh id {}", mesh.0))
                }
                _ => Ok(()),
            },
            _ => Ok(()),
        }
    }

    fn insert_builtin(&mut self, e: hecs::Entity, value: BuiltinValue) {
        // `e` was checked to exist, so inserting cannot fail.
        let _ = match value {
            BuiltinValue::Name(name) => self.state.world.insert_one(e, name),
            BuiltinValue::Transform(t) => self.state.world.insert_one(e, t),
            BuiltinValue::MeshRenderer(r) => self.state.world.insert_one(e, r),
            BuiltinValue::Camera(c) => self.state.world.insert_one(e, c),
            BuiltinValue::Light(l) => self.state.world.insert_one(e, l),
            BuiltinValue::RigidBody(b) => self.state.world.insert_one(e, b),
            BuiltinValue::Collider(c) => self.state.world.insert_one(e, c),
            _ => Ok(()),
        };
    }

    fn validate_transforms(&self, items: &[EntityTransform]) -> Result<(), CtxError> {
        for item in items {
            self.entity(item.entity)?;
            if !item.transform.is_finite() {
                return Err(CtxError::NonFinite {
                    entity: item.entity,
                    component: "Transform".into(),
                });
            }
        }
        Ok(())
    }

    fn write_transforms(world: &mut hecs::World, items: &[EntityTransform]) {
        // Fast path: `items` is usually the buffer `transforms()` filled from this same query,
        // in the same order; write it back in one pass. Any mismatch falls back to lookups.
        let query = world.query_mut::<(hecs::Entity, &mut Transform)>();
        let mut rows = query.into_iter();
        let mut written = 0;
        for item in items {
            match rows.next() {
                Some((e, t)) if to_api(e) == item.entity => {
                    *t = item.transform;
                    written += 1;
                }
                _ => break,
            }
        }
        drop(rows);
        for item in &items[written..] {
            let Some(e) = to_hecs(item.entity) else {
                continue;
            };
            if let Ok(t) = world.query_one_mut::<&mut Transform>(e) {
                *t = item.transform;
            } else {
                let _ = world.insert_one(e, item.transform);
            }
        }
    }
}

fn missing(entity: Entity, component: &str) -> CtxError {
    CtxError::MissingComponent {
        entity,
        component: component.to_owned(),
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
        self.state.input
    }

    fn request_quit(&mut self) {
        tracing::info!(plugin = self.plugin, "plugin requested quit");
        self.state.quit_requested = true;
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
        let placeholder = Entity::from_bits(0);
        for value in &builtins {
            self.validate(placeholder, value)?;
        }
        let e = self.state.world.spawn(());
        for value in builtins {
            self.insert_builtin(e, value);
        }
        if !blobs.is_empty() {
            let mut map = PluginComponents::default();
            for blob in blobs {
                map.0.insert(
                    blob.name,
                    StoredBlob {
                        format: blob.format,
                        bytes: blob.bytes,
                    },
                );
            }
            let _ = self.state.world.insert_one(e, map);
        }
        Ok(to_api(e))
    }

    fn despawn(&mut self, entity: Entity) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        self.state
            .world
            .despawn(e)
            .map_err(|_| CtxError::NoSuchEntity { entity })
    }

    fn contains(&self, entity: Entity) -> bool {
        self.entity(entity).is_ok()
    }

    fn get_builtin(&mut self, entity: Entity, id: BuiltinId) -> Result<BuiltinValue, CtxError> {
        let e = self.entity(entity)?;
        let world = &self.state.world;
        match id {
            BuiltinId::Name => world
                .get::<&Name>(e)
                .map(|n| BuiltinValue::Name((*n).clone()))
                .map_err(|_| missing(entity, id.name())),
            BuiltinId::Transform => world
                .get::<&Transform>(e)
                .map(|t| BuiltinValue::Transform(*t))
                .map_err(|_| missing(entity, id.name())),
            BuiltinId::MeshRenderer => world
                .get::<&MeshRenderer>(e)
                .map(|v| BuiltinValue::MeshRenderer(*v))
                .map_err(|_| missing(entity, id.name())),
            BuiltinId::Camera => world
                .get::<&Camera>(e)
                .map(|v| BuiltinValue::Camera(*v))
                .map_err(|_| missing(entity, id.name())),
            BuiltinId::Light => world
                .get::<&Light>(e)
                .map(|v| BuiltinValue::Light(*v))
                .map_err(|_| missing(entity, id.name())),
            BuiltinId::RigidBody => world
                .get::<&RigidBody>(e)
                .map(|v| BuiltinValue::RigidBody(*v))
                .map_err(|_| missing(entity, id.name())),
            BuiltinId::Collider => world
                .get::<&Collider>(e)
                .map(|v| BuiltinValue::Collider(*v))
                .map_err(|_| missing(entity, id.name())),
        }
    }

    fn set_builtin(&mut self, entity: Entity, value: BuiltinValue) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        self.validate(entity, &value)?;
        self.insert_builtin(e, value);
        Ok(())
    }

    fn remove_builtin(&mut self, entity: Entity, id: BuiltinId) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        let world = &mut self.state.world;
        let removed = match id {
            BuiltinId::Name => world.remove_one::<Name>(e).is_ok(),
            BuiltinId::Transform => world.remove_one::<Transform>(e).is_ok(),
            BuiltinId::MeshRenderer => world.remove_one::<MeshRenderer>(e).is_ok(),
            BuiltinId::Camera => world.remove_one::<Camera>(e).is_ok(),
            BuiltinId::Light => world.remove_one::<Light>(e).is_ok(),
            BuiltinId::RigidBody => world.remove_one::<RigidBody>(e).is_ok(),
            BuiltinId::Collider => world.remove_one::<Collider>(e).is_ok(),
        };
        if removed {
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
        if blob.name.is_empty() {
            return Err(CtxError::Invalid {
                message: "a plugin component needs a non-empty name".into(),
            });
        }
        let stored = StoredBlob {
            format: blob.format,
            bytes: blob.bytes,
        };
        let world = &mut self.state.world;
        if let Ok(mut map) = world.get::<&mut PluginComponents>(e) {
            map.0.insert(blob.name, stored);
            return Ok(());
        }
        let mut map = PluginComponents::default();
        map.0.insert(blob.name, stored);
        let _ = world.insert_one(e, map);
        Ok(())
    }

    fn remove_blob(&mut self, entity: Entity, name: &str) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        let mut map = self
            .state
            .world
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
        state.entity_buffer.clear();
        state
            .entity_buffer
            .extend(state.world.iter().map(|e| to_api(e.entity())));
        &state.entity_buffer
    }

    fn transforms(&mut self) -> &mut [EntityTransform] {
        let state = &mut *self.state;
        state.transform_buffer.clear();
        state.transform_buffer.extend(
            state
                .world
                .query_mut::<(hecs::Entity, &Transform)>()
                .into_iter()
                .map(|(e, t)| EntityTransform {
                    entity: to_api(e),
                    transform: *t,
                }),
        );
        &mut state.transform_buffer
    }

    fn commit_transforms(&mut self) -> Result<(), CtxError> {
        let items = std::mem::take(&mut self.state.transform_buffer);
        let result = self.validate_transforms(&items);
        if result.is_ok() {
            Self::write_transforms(&mut self.state.world, &items);
        }
        self.state.transform_buffer = items;
        result
    }

    fn set_transforms(&mut self, items: &[EntityTransform]) -> Result<(), CtxError> {
        self.validate_transforms(items)?;
        Self::write_transforms(&mut self.state.world, items);
        Ok(())
    }

    fn send(&mut self, name: &str, payload: &[u8]) {
        self.state.pending_events.push(Event::Custom(CustomEvent {
            name: name.to_owned(),
            sender: self.plugin.to_owned(),
            payload: payload.to_vec(),
        }));
    }

    fn request_plugin(&mut self, request: PluginRequest) {
        tracing::debug!(plugin = self.plugin, ?request, "plugin change requested");
        self.state.plugin_requests.push(request);
    }

    fn load_mesh(&mut self, path: &str) -> Result<MeshId, CtxError> {
        if path.is_empty() {
            return Err(CtxError::Invalid {
                message: "load_mesh needs a file path".into(),
            });
        }
        Ok(self.state.assets.mesh(std::path::Path::new(path)))
    }

    fn load_texture(&mut self, path: &str) -> Result<TextureId, CtxError> {
        if path.is_empty() {
            return Err(CtxError::Invalid {
                message: "load_texture needs a file path".into(),
            });
        }
        Ok(self.state.assets.texture(std::path::Path::new(path)))
    }

    fn set_camera(&mut self, entity: Entity) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        if self.state.world.get::<&Camera>(e).is_err() {
            return Err(missing(entity, "Camera"));
        }
        self.state.camera_override = Some(entity);
        Ok(())
    }

    fn draw_debug_lines(&mut self, lines: &[DebugLine]) {
        self.state.debug_lines.extend(
            lines
                .iter()
                .filter(|l| l.start.is_finite() && l.end.is_finite()),
        );
    }

    fn physics_command(&mut self, entity: Entity, command: PhysicsCommand) -> Result<(), CtxError> {
        let e = self.entity(entity)?;
        if self.state.world.get::<&Collider>(e).is_err() {
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
}
