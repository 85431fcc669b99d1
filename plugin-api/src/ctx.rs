//! [`Ctx`]: the plugin's handle to the host during one lifecycle call.

use abi_stable::std_types::{RResult, RVec};

use crate::__ffi::{BlobFfi, CharacterStepFfi, HostRef, PluginOpFfi, RayFfi, SweepFfi};
use crate::component::component_type::{decode, BundleParts};
use crate::glam::Vec3;
use crate::host::PhysicsCommand;
mod tool_calls;

use crate::{
    BlobFormat, BuiltinId, BuiltinValue, Bundle, CharacterController, CharacterMove, ColliderShape,
    Component, ComponentType, CtxError, DebugLine, Entity, EntityTransform, GlobalTransform,
    InputState, KeepPose, LogLevel, MeshId, Message, Parent, QueryFilter, RayHit, TextureId, Time,
    Transform,
};

/// The host, as a plugin reaches it: the world, the clock, input, events and logging.
///
/// A `Ctx` is lent to each lifecycle call and cannot be kept. Calls that change the world
/// validate their input and return [`CtxError`] instead of writing bad data.
///
/// ```no_run
/// # use onyx_plugin_api::*;
/// # fn demo(ctx: &mut Ctx) -> Result<(), CtxError> {
/// let crate_ = ctx.spawn((Name::new("crate"), Transform::from_xyz(0.0, 2.0, 0.0)))?;
/// let mut t: Transform = ctx.get(crate_)?;
/// t.translation.y += 1.0;
/// ctx.set(crate_, t)?;
/// ctx.info(format!("crate is at {}", t.translation));
/// # Ok(()) }
/// ```
pub struct Ctx<'a> {
    host: HostRef<'a>,
}

fn ok<T>(result: RResult<T, crate::__ffi::CtxErrorFfi>) -> Result<T, CtxError> {
    result.into_result().map_err(Into::into)
}

impl<'a> Ctx<'a> {
    #[doc(hidden)]
    pub fn new(host: HostRef<'a>) -> Self {
        Self { host }
    }

    /// The name of the plugin being called (its crate name).
    pub fn plugin_name(&self) -> &str {
        self.host.plugin_name().as_str()
    }

    // ----- entities -----

    /// Creates an entity with `components` (one component or a tuple of up to eight).
    pub fn spawn(&mut self, components: impl Bundle) -> Result<Entity, CtxError> {
        let mut parts = BundleParts::default();
        components.write_to(&mut parts)?;
        ok(self.host.spawn(parts.builtins, parts.blobs))
    }

    /// Removes `entity` and all its components. Its children stay where they are in the
    /// world and become roots (see [`Ctx::despawn_recursive`] to remove them too).
    pub fn despawn(&mut self, entity: Entity) -> Result<(), CtxError> {
        ok(self.host.despawn(entity))
    }

    /// Removes `entity` with all its descendants.
    pub fn despawn_recursive(&mut self, entity: Entity) -> Result<(), CtxError> {
        ok(self.host.despawn_recursive(entity))
    }

    /// Whether `entity` exists.
    pub fn contains(&self, entity: Entity) -> bool {
        self.host.contains(entity)
    }

    /// Every entity in the world (a view into a host buffer, valid until the next call).
    pub fn entities(&mut self) -> &[Entity] {
        self.host.entities().as_slice()
    }

    // ----- the scene graph -----

    /// Puts `entity` under `parent`, keeping its world pose ([`KeepPose::World`]: its local
    /// transform is recomputed) or its local transform ([`KeepPose::Local`]: it moves with
    /// the parent). Refused with [`CtxError::InvalidParent`] when `parent` is the entity,
    /// one of its descendants, or does not exist.
    pub fn set_parent(
        &mut self,
        entity: Entity,
        parent: Entity,
        keep: KeepPose,
    ) -> Result<(), CtxError> {
        if parent.to_bits() == 0 {
            return Err(CtxError::InvalidParent {
                entity,
                parent,
                problem: crate::ParentProblem::Missing,
            });
        }
        ok(self.host.set_parent(entity, parent, keep))
    }

    /// Makes `entity` a root again, keeping its world pose or its local transform.
    pub fn clear_parent(&mut self, entity: Entity, keep: KeepPose) -> Result<(), CtxError> {
        ok(self.host.set_parent(entity, Entity::from_bits(0), keep))
    }

    /// The parent of `entity`, if it has one.
    pub fn parent(&mut self, entity: Entity) -> Result<Option<Entity>, CtxError> {
        match self.get::<Parent>(entity) {
            Ok(Parent(parent)) => Ok(Some(parent)),
            Err(CtxError::MissingComponent { .. }) => Ok(None),
            Err(e) => Err(e),
        }
    }

    /// The children of `entity`, in the order they were attached.
    pub fn children(&mut self, entity: Entity) -> Result<Vec<Entity>, CtxError> {
        ok(self.host.children(entity)).map(RVec::into_vec)
    }

    /// Where `entity` is in the world: its [`Transform`] with every ancestor's applied
    /// (up to date with every write made so far, this call included).
    pub fn world_pose(&mut self, entity: Entity) -> Result<GlobalTransform, CtxError> {
        ok(self.host.world_pose(entity)).map(Into::into)
    }

    /// Moves `entity` to `pose` in the world: writes the local [`Transform`] that puts it
    /// there under its parent (all of `pose` for an entity without one).
    pub fn set_world_pose(&mut self, entity: Entity, pose: Transform) -> Result<(), CtxError> {
        ok(self.host.set_world_pose(entity, pose.into()))
    }

    // ----- components -----

    /// Reads a component of `entity`: `ctx.get::<Transform>(e)`.
    pub fn get<T: ComponentType>(&mut self, entity: Entity) -> Result<T, CtxError> {
        T::get_from(self, entity)
    }

    /// Inserts or replaces a component of `entity`.
    pub fn set<T: ComponentType>(&mut self, entity: Entity, value: T) -> Result<(), CtxError> {
        value.set_into(self, entity)
    }

    /// Removes a component from `entity`: `ctx.remove::<Name>(e)`.
    pub fn remove<T: ComponentType>(&mut self, entity: Entity) -> Result<(), CtxError> {
        T::remove_from(self, entity)
    }

    /// Every entity holding the plugin component `T`, with its value.
    pub fn query<T: Component>(&mut self) -> Result<Vec<(Entity, T)>, CtxError> {
        let rows = self.host.query_blobs(T::NAME.into());
        rows.into_iter()
            .map(|row| Ok((row.entity, decode::<T>(row.format, &row.bytes)?)))
            .collect()
    }

    /// Reads a plugin component stored as raw bytes under `name`.
    pub fn get_raw(&mut self, entity: Entity, name: &str) -> Result<Vec<u8>, CtxError> {
        Ok(self.raw_get_blob(entity, name)?.bytes.into_vec())
    }

    /// Stores `bytes` as the plugin component `name` of `entity` (shown as base64 in dumps).
    pub fn set_raw(&mut self, entity: Entity, name: &str, bytes: &[u8]) -> Result<(), CtxError> {
        self.raw_set_blob(entity, name, BlobFormat::Raw, RVec::from(bytes))
    }

    /// Removes the plugin component `name` (raw or serde) from `entity`.
    pub fn remove_raw(&mut self, entity: Entity, name: &str) -> Result<(), CtxError> {
        self.raw_remove_blob(entity, name)
    }

    // ----- bulk transforms -----

    /// Every entity with a [`Transform`](crate::Transform), in one call: a view into a host
    /// buffer, valid until the next call on this `Ctx`.
    pub fn transforms(&mut self) -> &[EntityTransform] {
        self.host.transforms().into_slice()
    }

    /// Writes many transforms in one call, all or nothing: if any is non-finite or names a
    /// missing entity, none is written.
    pub fn set_transforms(&mut self, items: &[EntityTransform]) -> Result<(), CtxError> {
        ok(self.host.set_transforms(items.into()))
    }

    /// Edits every transform in place, in one round trip and without copies:
    ///
    /// ```no_run
    /// # use onyx_plugin_api::*;
    /// # fn demo(ctx: &mut Ctx) -> Result<(), CtxError> {
    /// ctx.update_transforms(|items| {
    ///     for item in items {
    ///         item.transform.translation.y -= 0.1;
    ///     }
    /// })?;
    /// # Ok(()) }
    /// ```
    ///
    /// The result is validated like [`Ctx::set_transforms`].
    pub fn update_transforms(
        &mut self,
        edit: impl FnOnce(&mut [EntityTransform]),
    ) -> Result<(), CtxError> {
        edit(self.host.transforms().into_mut_slice());
        ok(self.host.commit_transforms())
    }

    // ----- time and input -----

    /// The host clock.
    pub fn time(&self) -> Time {
        self.host.time()
    }

    /// Keyboard and mouse state for this frame.
    pub fn input(&self) -> InputState {
        self.host.input()
    }

    /// Pauses (or resumes) fixed steps; `on_update` keeps running with `delta` = 0.
    pub fn set_paused(&mut self, paused: bool) {
        self.host.set_paused(paused)
    }

    /// Runs simulation time at `scale` × real time (finite, ≥ 0).
    pub fn set_time_scale(&mut self, scale: f32) -> Result<(), CtxError> {
        ok(self.host.set_time_scale(scale))
    }

    /// Runs exactly one fixed step next frame, even while paused (the editor's "step").
    pub fn step_once(&mut self) {
        self.host.step_once()
    }

    /// Asks the host to finish this frame and quit.
    pub fn request_quit(&mut self) {
        self.host.request_quit()
    }

    /// Keeps the window open after the user asked to close it: call it while handling
    /// [`WindowEvent::CloseRequested`](crate::WindowEvent::CloseRequested) when there is
    /// unsaved work, ask the user, then [`Ctx::request_quit`] if they agree. Without it the
    /// host quits after the frame that delivered the event.
    ///
    /// ```no_run
    /// # use onyx_plugin_api::{Ctx, Event, WindowEvent};
    /// # struct Editor { unsaved: bool, asking: bool }
    /// # impl Editor {
    /// fn on_event(&mut self, ctx: &mut Ctx, event: &Event) {
    ///     if matches!(event, Event::Window(WindowEvent::CloseRequested)) && self.unsaved {
    ///         ctx.prevent_close();
    ///         self.asking = true; // draw_gui shows "Save changes?" next
    ///     }
    /// }
    /// # }
    /// ```
    pub fn prevent_close(&mut self) {
        self.host.prevent_close()
    }

    // ----- events -----

    /// Sends a typed custom event to every plugin (delivered next frame, sender included).
    pub fn send<M: Message>(&mut self, message: &M) -> Result<(), CtxError> {
        let payload = serde_json::to_vec(message).map_err(|e| CtxError::Encode {
            component: M::NAME.to_owned(),
            message: e.to_string(),
        })?;
        self.send_raw(M::NAME, &payload);
        Ok(())
    }

    /// Sends a custom event with a raw payload.
    pub fn send_raw(&mut self, name: &str, payload: &[u8]) {
        self.host.send(name.into(), payload.into())
    }

    // ----- plugins -----

    /// Asks the host to reload plugin `name` from its file after this frame (hot reload:
    /// state carried over, entities untouched; a faulted plugin is revived).
    pub fn reload_plugin(&mut self, name: &str) {
        self.host
            .request_plugin_op(PluginOpFfi::Reload, name.into())
    }

    /// Asks the host to reload every plugin loaded from a file, after this frame.
    pub fn reload_all_plugins(&mut self) {
        self.host
            .request_plugin_op(PluginOpFfi::ReloadAll, "".into())
    }

    /// Asks the host to load a plugin (a library path or a NAME) after this frame. Success
    /// or failure arrives as a platform event.
    pub fn load_plugin(&mut self, spec: &str) {
        self.host.request_plugin_op(PluginOpFfi::Load, spec.into())
    }

    /// Asks the host to detach and remove plugin `name` after this frame.
    pub fn unload_plugin(&mut self, name: &str) {
        self.host
            .request_plugin_op(PluginOpFfi::Unload, name.into())
    }

    // ----- rendering -----

    /// Loads a model (OBJ + MTL) once per path, relative to the working directory, and
    /// returns its mesh id for a [`MeshRenderer`](crate::MeshRenderer). A file that cannot be
    /// loaded gives an error naming it; entities using the id are drawn with a visible
    /// fallback (a magenta checker).
    pub fn load_mesh(&mut self, path: &str) -> Result<MeshId, CtxError> {
        ok(self.host.load_mesh(path.into()))
    }

    /// Loads an image (PNG, JPEG) once per path and returns its texture id.
    pub fn load_texture(&mut self, path: &str) -> Result<TextureId, CtxError> {
        ok(self.host.load_texture(path.into()))
    }

    /// Draws through the [`Camera`](crate::Camera) of `entity` from now on.
    pub fn set_camera(&mut self, entity: Entity) -> Result<(), CtxError> {
        ok(self.host.set_camera(entity))
    }

    /// Draws these line segments this frame (call each frame to keep them).
    pub fn draw_debug_lines(&mut self, lines: &[DebugLine]) {
        self.host.draw_debug_lines(lines.into())
    }

    // ----- physics -----

    /// Pushes the body of `entity` with a force (newtons, world axes) during the next fixed
    /// step. Forces add up and are cleared after each step.
    pub fn apply_force(&mut self, entity: Entity, force: Vec3) -> Result<(), CtxError> {
        self.physics(entity, PhysicsCommand::Force(force.to_array()))
    }

    /// Changes the momentum of the body of `entity` at once by `impulse` (N·s).
    pub fn apply_impulse(&mut self, entity: Entity, impulse: Vec3) -> Result<(), CtxError> {
        self.physics(entity, PhysicsCommand::Impulse(impulse.to_array()))
    }

    /// Twists the body of `entity` with a torque (N·m) during the next fixed step.
    pub fn apply_torque(&mut self, entity: Entity, torque: Vec3) -> Result<(), CtxError> {
        self.physics(entity, PhysicsCommand::Torque(torque.to_array()))
    }

    /// Sets the linear (m/s) and angular (rad/s) velocity of the body of `entity`.
    pub fn set_velocity(
        &mut self,
        entity: Entity,
        linear: Vec3,
        angular: Vec3,
    ) -> Result<(), CtxError> {
        let command = PhysicsCommand::Velocity {
            linear: linear.to_array(),
            angular: angular.to_array(),
        };
        self.physics(entity, command)
    }

    /// The first collider hit by a ray from `origin` along `direction`, within
    /// `max_distance` metres.
    pub fn raycast(&mut self, origin: Vec3, direction: Vec3, max_distance: f32) -> Option<RayHit> {
        let ray = RayFfi {
            origin: origin.to_array(),
            direction: direction.to_array(),
            max_distance,
        };
        self.host.raycast(ray).into_option()
    }

    /// The entities whose colliders overlap `shape` placed at `pose` (scaled with its
    /// `scale` as a collider is), exactly (the narrowphase's test, not bounding boxes);
    /// touching counts. Each entity once, in no set order.
    ///
    /// ```no_run
    /// # use onyx_plugin_api::*;
    /// # fn demo(ctx: &mut Ctx, player: Entity) -> Result<(), CtxError> {
    /// let near = ctx.overlap(
    ///     ColliderShape::Sphere { radius: 2.0 },
    ///     Transform::from_xyz(0.0, 1.0, 0.0),
    ///     &QueryFilter::default().excluding(player),
    /// )?;
    /// # let _ = near; Ok(()) }
    /// ```
    ///
    /// # Errors
    /// [`CtxError::Invalid`] for a shape other than a sphere, a box or a capsule, a size
    /// that is not above zero, or a non-finite pose.
    pub fn overlap(
        &mut self,
        shape: ColliderShape,
        pose: Transform,
        filter: &QueryFilter,
    ) -> Result<Vec<Entity>, CtxError> {
        ok(self.host.overlap(shape, pose.into(), (*filter).into())).map(RVec::into_vec)
    }

    /// Sweeps `shape` from `pose` along `direction` (need not be normalised) for up to
    /// `max_distance` metres, without turning, and returns the first collider it meets:
    /// the entity, the point, the surface normal (facing the shape) and the distance
    /// travelled. Contacts it only slides along or moves away from do not stop it; one it
    /// starts inside and moves further into hits at distance 0.
    ///
    /// # Errors
    /// As [`Ctx::overlap`].
    pub fn shape_cast(
        &mut self,
        shape: ColliderShape,
        pose: Transform,
        direction: Vec3,
        max_distance: f32,
        filter: &QueryFilter,
    ) -> Result<Option<RayHit>, CtxError> {
        let sweep = SweepFfi {
            direction: direction.to_array(),
            max_distance,
        };
        ok(self
            .host
            .shape_cast(shape, pose.into(), sweep, (*filter).into()))
        .map(|hit| hit.into_option())
    }

    /// The current coordinate of the [`Joint`](crate::Joint) on `entity`, at the bodies'
    /// poses after the last step: a revolute joint's angle (radians, in (−π, π], 0 where it
    /// was made), a prismatic joint's position along its axis (metres), a distance joint's
    /// length (metres), a spherical joint's twist (radians). `None` for a fixed joint and a
    /// joint not made yet (it is made at the next fixed step). A broken joint still reads
    /// where its two sides are.
    ///
    /// # Errors
    /// [`CtxError::MissingComponent`] when `entity` has no `Joint`.
    pub fn joint_coordinate(&mut self, entity: Entity) -> Result<Option<f32>, CtxError> {
        ok(self.host.joint_coordinate(entity)).map(|c| c.into_option())
    }

    /// Moves the character `entity` (a [`RigidBody`](crate::RigidBody) of kind
    /// `Kinematic` with a solid convex collider — a capsule, typically) by `desired`
    /// (world axes, metres: its velocity times this step, gravity included) as far as the
    /// world lets it: it slides along walls, walks up slopes up to the largest angle and
    /// steps up to the step height, stays on the ground going down, and pushes dynamic
    /// bodies (see [`CharacterController`]). Its transform moves at once; its body follows
    /// in the next fixed step. Call it from `on_fixed_update`, once per step.
    ///
    /// ```no_run
    /// # use onyx_plugin_api::*;
    /// # fn demo(ctx: &mut Ctx, player: Entity, velocity: &mut glam::Vec3, dt: f32) -> Result<(), CtxError> {
    /// velocity.y -= 9.81 * dt;
    /// let moved = ctx.move_character(player, *velocity * dt, &CharacterController::default())?;
    /// if moved.grounded {
    ///     velocity.y = 0.0;
    /// }
    /// # Ok(()) }
    /// ```
    ///
    /// # Errors
    /// [`CtxError::Invalid`] when `entity` has no physics body (yet: bodies are made at the
    /// next fixed step) or no solid convex collider, or `desired` is not finite.
    pub fn move_character(
        &mut self,
        entity: Entity,
        desired: Vec3,
        controller: &CharacterController,
    ) -> Result<CharacterMove, CtxError> {
        let step = CharacterStepFfi {
            desired: desired.to_array(),
            controller: *controller,
        };
        ok(self.host.move_character(entity, step)).map(Into::into)
    }

    fn physics(&mut self, entity: Entity, command: PhysicsCommand) -> Result<(), CtxError> {
        ok(self.host.physics_command(entity, command))
    }

    // ----- logging -----

    /// Logs through the host's `tracing`, tagged with this plugin's name.
    pub fn log(&mut self, level: LogLevel, message: impl AsRef<str>) {
        self.host.log(level, message.as_ref().into())
    }

    /// Logs at [`LogLevel::Trace`].
    pub fn trace(&mut self, message: impl AsRef<str>) {
        self.log(LogLevel::Trace, message)
    }

    /// Logs at [`LogLevel::Debug`].
    pub fn debug(&mut self, message: impl AsRef<str>) {
        self.log(LogLevel::Debug, message)
    }

    /// Logs at [`LogLevel::Info`].
    pub fn info(&mut self, message: impl AsRef<str>) {
        self.log(LogLevel::Info, message)
    }

    /// Logs at [`LogLevel::Warn`].
    pub fn warn(&mut self, message: impl AsRef<str>) {
        self.log(LogLevel::Warn, message)
    }

    /// Logs at [`LogLevel::Error`].
    pub fn error(&mut self, message: impl AsRef<str>) {
        self.log(LogLevel::Error, message)
    }

    // ----- built-ins by id (tools), and raw access used by `ComponentType` -----

    /// Reads the built-in component `id` of `entity`.
    pub fn get_builtin(&mut self, entity: Entity, id: BuiltinId) -> Result<BuiltinValue, CtxError> {
        ok(self.host.get_builtin(entity, id)).map(Into::into)
    }

    /// Inserts or replaces a built-in component of `entity` (checked like every write).
    pub fn set_builtin(&mut self, entity: Entity, value: BuiltinValue) -> Result<(), CtxError> {
        ok(self.host.set_builtin(entity, value.into()))
    }

    /// Removes the built-in component `id` from `entity`.
    pub fn remove_builtin(&mut self, entity: Entity, id: BuiltinId) -> Result<(), CtxError> {
        ok(self.host.remove_builtin(entity, id))
    }

    pub(crate) fn raw_get_blob(&mut self, entity: Entity, name: &str) -> Result<BlobFfi, CtxError> {
        ok(self.host.get_blob(entity, name.into()))
    }

    pub(crate) fn raw_set_blob(
        &mut self,
        entity: Entity,
        name: &str,
        format: BlobFormat,
        bytes: RVec<u8>,
    ) -> Result<(), CtxError> {
        let blob = BlobFfi {
            name: name.into(),
            format,
            bytes,
        };
        ok(self.host.set_blob(entity, blob))
    }

    pub(crate) fn raw_remove_blob(&mut self, entity: Entity, name: &str) -> Result<(), CtxError> {
        ok(self.host.remove_blob(entity, name.into()))
    }
}
