//! [`HostServices`]: what a host must provide to plugins, in plain Rust.

use crate::glam::Vec3;
use crate::host::Blob;
use crate::{
    BuiltinId, BuiltinValue, CharacterController, CharacterMove, ColliderShape, CtxError,
    DebugLine, Entity, EntityTransform, GlobalTransform, InputState, KeepPose, LogLevel, MeshId,
    QueryFilter, RayHit, TextureId, Time, Transform,
};

fn unsupported(service: &str) -> CtxError {
    CtxError::Unsupported {
        service: service.to_owned(),
    }
}

/// The services behind [`Ctx`](crate::Ctx), implemented by the host for the duration of one
/// plugin call. The SDK turns an implementation into the ABI-stable object that crosses
/// the boundary; implementors never see FFI types.
///
/// Implementations must not panic (a panic is caught and turned into an error, but it is a
/// host bug). Every method that changes the world validates its input and returns a
/// [`CtxError`] instead of writing bad data. The tool services (editor) are the supertrait
/// [`ToolServices`](crate::host::ToolServices), defaulted.
pub trait HostServices: crate::host::ToolServices {
    /// Name of the plugin being called.
    fn plugin_name(&self) -> &str;
    /// Logs `message` at `level` on behalf of the plugin.
    fn log(&mut self, level: LogLevel, message: &str);
    /// The clock.
    fn time(&self) -> Time;
    /// Keyboard and mouse state.
    fn input(&self) -> InputState;
    /// Ends the run after this frame.
    fn request_quit(&mut self);
    /// Keeps the window open although the user asked to close it this frame.
    fn prevent_close(&mut self);
    /// Pauses or resumes fixed steps.
    fn set_paused(&mut self, paused: bool);
    /// Sets the time scale (finite, ≥ 0).
    fn set_time_scale(&mut self, scale: f32) -> Result<(), CtxError>;
    /// Runs exactly one fixed step next frame, even while paused.
    fn step_once(&mut self);
    /// Creates an entity with these components.
    fn spawn(&mut self, builtins: Vec<BuiltinValue>, blobs: Vec<Blob>) -> Result<Entity, CtxError>;
    /// Removes an entity and all its components; its children stay where they are in the
    /// world, as roots.
    fn despawn(&mut self, entity: Entity) -> Result<(), CtxError>;
    /// Removes an entity with all its descendants.
    fn despawn_recursive(&mut self, entity: Entity) -> Result<(), CtxError>;
    /// Whether the entity exists.
    fn contains(&self, entity: Entity) -> bool;
    /// Puts `entity` under `parent` (`None`: makes it a root), keeping its world or local pose.
    fn set_parent(
        &mut self,
        entity: Entity,
        parent: Option<Entity>,
        keep: KeepPose,
    ) -> Result<(), CtxError>;
    /// The children of `entity`, in the order they were attached.
    fn children(&mut self, entity: Entity) -> Result<Vec<Entity>, CtxError>;
    /// The world pose of `entity` (its transform with every ancestor's applied).
    fn world_pose(&mut self, entity: Entity) -> Result<GlobalTransform, CtxError>;
    /// Moves `entity` to the world pose `pose`, writing the local transform that puts it there.
    fn set_world_pose(&mut self, entity: Entity, pose: Transform) -> Result<(), CtxError>;
    /// Reads a built-in component.
    fn get_builtin(&mut self, entity: Entity, id: BuiltinId) -> Result<BuiltinValue, CtxError>;
    /// Inserts or replaces a built-in component.
    fn set_builtin(&mut self, entity: Entity, value: BuiltinValue) -> Result<(), CtxError>;
    /// Removes a built-in component.
    fn remove_builtin(&mut self, entity: Entity, id: BuiltinId) -> Result<(), CtxError>;
    /// Reads a plugin component.
    fn get_blob(&mut self, entity: Entity, name: &str) -> Result<Blob, CtxError>;
    /// Inserts or replaces a plugin component.
    fn set_blob(&mut self, entity: Entity, blob: Blob) -> Result<(), CtxError>;
    /// Removes a plugin component.
    fn remove_blob(&mut self, entity: Entity, name: &str) -> Result<(), CtxError>;
    /// Every entity that has the plugin component `name`, with its value.
    fn query_blobs(&mut self, name: &str) -> Vec<(Entity, Blob)>;
    /// Every entity, in a buffer owned by the host.
    fn entities(&mut self) -> &[Entity];
    /// Every entity with a transform, copied into a buffer owned by the host that the plugin
    /// may edit in place and hand back with [`HostServices::commit_transforms`].
    fn transforms(&mut self) -> &mut [EntityTransform];
    /// Writes the buffer last returned by [`HostServices::transforms`] back to the world.
    fn commit_transforms(&mut self) -> Result<(), CtxError>;
    /// Writes these transforms to the world (all or nothing).
    fn set_transforms(&mut self, items: &[EntityTransform]) -> Result<(), CtxError>;
    /// Queues a custom event for every plugin, delivered next frame.
    fn send(&mut self, name: &str, payload: &[u8]);
    /// Queues a change to the set of plugins, carried out after the frame.
    fn request_plugin(&mut self, request: PluginRequest);
    /// Loads (once per path) a model file and returns its mesh id.
    fn load_mesh(&mut self, path: &str) -> Result<MeshId, CtxError>;
    /// Loads (once per path) an image file and returns its texture id.
    fn load_texture(&mut self, path: &str) -> Result<TextureId, CtxError>;
    /// Draws through the camera of `entity`.
    fn set_camera(&mut self, entity: Entity) -> Result<(), CtxError>;
    /// Draws these lines this frame.
    fn draw_debug_lines(&mut self, lines: &[DebugLine]);
    /// Applies a force, impulse, torque or velocity to the body of `entity`.
    fn physics_command(&mut self, entity: Entity, command: PhysicsCommand) -> Result<(), CtxError>;
    /// The first collider along a ray, if any within `max_distance`.
    fn raycast(&mut self, origin: Vec3, direction: Vec3, max_distance: f32) -> Option<RayHit>;
    /// The entities whose colliders overlap `shape` placed (and scaled) at `pose`.
    fn overlap(
        &mut self,
        shape: ColliderShape,
        pose: Transform,
        filter: QueryFilter,
    ) -> Result<Vec<Entity>, CtxError> {
        let _ = (shape, pose, filter);
        Err(unsupported("overlap"))
    }
    /// The first collider `shape` at `pose` meets swept along `direction` within
    /// `max_distance`.
    fn shape_cast(
        &mut self,
        shape: ColliderShape,
        pose: Transform,
        direction: Vec3,
        max_distance: f32,
        filter: QueryFilter,
    ) -> Result<Option<RayHit>, CtxError> {
        let _ = (shape, pose, direction, max_distance, filter);
        Err(unsupported("shape_cast"))
    }
    /// The current coordinate of the joint on `entity` (angle, position or length).
    fn joint_coordinate(&mut self, entity: Entity) -> Result<Option<f32>, CtxError> {
        let _ = entity;
        Err(unsupported("joint_coordinate"))
    }
    /// Moves the kinematic character `entity` by `desired` as far as the world lets it.
    fn move_character(
        &mut self,
        entity: Entity,
        desired: Vec3,
        controller: &CharacterController,
    ) -> Result<CharacterMove, CtxError> {
        let _ = (entity, desired, controller);
        Err(unsupported("move_character"))
    }
}

/// Something a plugin does to a body ([`Ctx::apply_force`](crate::Ctx::apply_force), …).
#[repr(C, u8)]
#[derive(abi_stable::StableAbi, Clone, Copy, Debug, PartialEq)]
pub enum PhysicsCommand {
    /// Add a force (N) at the centre of mass for the next fixed step.
    Force([f32; 3]),
    /// Add a torque (N·m) for the next fixed step.
    Torque([f32; 3]),
    /// Change the momentum at once by an impulse (N·s) at the centre of mass.
    Impulse([f32; 3]),
    /// Set linear (m/s) and angular (rad/s) velocity.
    Velocity {
        /// Linear velocity.
        linear: [f32; 3],
        /// Angular velocity.
        angular: [f32; 3],
    },
}

/// A change to the set of plugins that a plugin asked for (the editor's Plugins menu).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PluginRequest {
    /// Reload this plugin from its file.
    Reload(String),
    /// Reload every plugin loaded from a file.
    ReloadAll,
    /// Load a plugin by path or NAME.
    Load(String),
    /// Detach and remove this plugin.
    Unload(String),
}
