//! [`HostObject`]: the host's services as a `#[sabi_trait]` object (a prefix vtable of
//! `extern "C"` functions plus an opaque pointer), and [`HostBridge`], which builds it from
//! any safe [`HostServices`] implementation.

// The generated trait object types carry no docs of their own.
// `#[sabi_trait]` expands to impls of abi_stable traits inside a generated module.
#![allow(missing_docs, non_camel_case_types, non_local_definitions)]

use std::panic::{catch_unwind, AssertUnwindSafe};

use abi_stable::{
    sabi_trait,
    std_types::{ROption, RResult, RSlice, RSliceMut, RStr, RString, RVec},
};

use super::TransformFfi;
use super::{BlobFfi, BuiltinFfi, ComponentsFfi, CtxErrorFfi, EntityBlobFfi};
use super::{BoundsFfi, EntityListFfi, GlobalTransformFfi, ReportFfi, SceneOpFfi, ScreenPointFfi};
use crate::host::PhysicsCommand;
use crate::host::PlayCommand;
use crate::host::{HostServices, PluginRequest};
use crate::tools::{PlayMode, RenderOverrides};
use crate::{
    BuiltinId, CharacterController, CharacterMove, ColliderShape, CtxError, DebugLine, Entity,
    EntityTransform, InputState, KeepPose, LogLevel, MeshId, QueryFilter, RayHit, TextureId, Time,
};

#[sabi_trait]
pub trait HostObject {
    fn plugin_name(&self) -> RStr<'_>;
    fn log(&mut self, level: LogLevel, message: RStr<'_>);
    fn time(&self) -> Time;
    fn input(&self) -> InputState;
    fn request_quit(&mut self);
    fn prevent_close(&mut self);
    fn set_paused(&mut self, paused: bool);
    fn set_time_scale(&mut self, scale: f32) -> RResult<(), CtxErrorFfi>;
    fn step_once(&mut self);
    fn spawn(
        &mut self,
        builtins: RVec<BuiltinFfi>,
        blobs: RVec<BlobFfi>,
    ) -> RResult<Entity, CtxErrorFfi>;
    fn despawn(&mut self, entity: Entity) -> RResult<(), CtxErrorFfi>;
    fn despawn_recursive(&mut self, entity: Entity) -> RResult<(), CtxErrorFfi>;
    fn contains(&self, entity: Entity) -> bool;
    /// `parent` with bits 0: no parent.
    fn set_parent(
        &mut self,
        entity: Entity,
        parent: Entity,
        keep: KeepPose,
    ) -> RResult<(), CtxErrorFfi>;
    fn children(&mut self, entity: Entity) -> RResult<RVec<Entity>, CtxErrorFfi>;
    fn world_pose(&mut self, entity: Entity) -> RResult<GlobalTransformFfi, CtxErrorFfi>;
    fn set_world_pose(&mut self, entity: Entity, pose: TransformFfi) -> RResult<(), CtxErrorFfi>;
    fn get_builtin(&mut self, entity: Entity, id: BuiltinId) -> RResult<BuiltinFfi, CtxErrorFfi>;
    fn set_builtin(&mut self, entity: Entity, value: BuiltinFfi) -> RResult<(), CtxErrorFfi>;
    fn remove_builtin(&mut self, entity: Entity, id: BuiltinId) -> RResult<(), CtxErrorFfi>;
    fn get_blob(&mut self, entity: Entity, name: RStr<'_>) -> RResult<BlobFfi, CtxErrorFfi>;
    fn set_blob(&mut self, entity: Entity, blob: BlobFfi) -> RResult<(), CtxErrorFfi>;
    fn remove_blob(&mut self, entity: Entity, name: RStr<'_>) -> RResult<(), CtxErrorFfi>;
    fn query_blobs(&mut self, name: RStr<'_>) -> RVec<EntityBlobFfi>;
    fn entities(&mut self) -> RSlice<'_, Entity>;
    fn transforms(&mut self) -> RSliceMut<'_, EntityTransform>;
    fn commit_transforms(&mut self) -> RResult<(), CtxErrorFfi>;
    fn set_transforms(&mut self, items: RSlice<'_, EntityTransform>) -> RResult<(), CtxErrorFfi>;
    fn send(&mut self, name: RStr<'_>, payload: RSlice<'_, u8>);
    fn request_plugin_op(&mut self, op: PluginOpFfi, argument: RStr<'_>);
    fn load_mesh(&mut self, path: RStr<'_>) -> RResult<MeshId, CtxErrorFfi>;
    fn load_texture(&mut self, path: RStr<'_>) -> RResult<TextureId, CtxErrorFfi>;
    fn set_camera(&mut self, entity: Entity) -> RResult<(), CtxErrorFfi>;
    fn draw_debug_lines(&mut self, lines: RSlice<'_, DebugLine>);
    fn physics_command(
        &mut self,
        entity: Entity,
        command: PhysicsCommand,
    ) -> RResult<(), CtxErrorFfi>;
    fn raycast(&mut self, ray: RayFfi) -> ROption<RayHit>;
    // ----- tool services (appended; see `host::ToolServices`) -----
    fn entity_list(&mut self) -> EntityListFfi;
    fn host_report(&mut self, report: ReportFfi, argument: u64) -> RResult<RVec<u8>, CtxErrorFfi>;
    fn components_of(&mut self, entity: Entity) -> RResult<ComponentsFfi, CtxErrorFfi>;
    fn scene_op(&mut self, op: SceneOpFfi, path: RStr<'_>) -> RResult<(), CtxErrorFfi>;
    fn scene_path(&mut self) -> ROption<RString>;
    fn play_command(&mut self, command: PlayCommand);
    fn play_mode(&self) -> PlayMode;
    fn register_script(
        &mut self,
        name: RStr<'_>,
        default_params: RStr<'_>,
    ) -> RResult<(), CtxErrorFfi>;
    fn screen_ray(&mut self, point: ScreenPointFfi) -> ROption<RayFfi>;
    fn set_render_overrides(&mut self, overrides: RenderOverrides);
    fn render_overrides(&self) -> RenderOverrides;
    fn pick(&mut self, ray: RayFfi) -> ROption<RayHit>;
    fn local_bounds(&mut self, entity: Entity) -> ROption<BoundsFfi>;
    fn import_gltf(&mut self, path: RStr<'_>) -> RResult<Entity, CtxErrorFfi>;
    // ----- physics queries, joints and characters (appended in 0.7) -----
    fn overlap(
        &mut self,
        shape: ColliderShape,
        pose: TransformFfi,
        filter: QueryFilterFfi,
    ) -> RResult<RVec<Entity>, CtxErrorFfi>;
    fn shape_cast(
        &mut self,
        shape: ColliderShape,
        pose: TransformFfi,
        sweep: SweepFfi,
        filter: QueryFilterFfi,
    ) -> RResult<ROption<RayHit>, CtxErrorFfi>;
    fn joint_coordinate(&mut self, entity: Entity) -> RResult<ROption<f32>, CtxErrorFfi>;
    fn move_character(
        &mut self,
        entity: Entity,
        step: CharacterStepFfi,
    ) -> RResult<CharacterMoveFfi, CtxErrorFfi>;
}

/// One move of a character: the move wanted (world axes, metres) and how to make it.
#[repr(C)]
#[derive(abi_stable::StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct CharacterStepFfi {
    pub desired: [f32; 3],
    pub controller: CharacterController,
}

/// A [`QueryFilter`], as plain data (`exclude` bits 0: none).
#[repr(C)]
#[derive(abi_stable::StableAbi, Clone, Copy, Debug, PartialEq, Eq)]
pub struct QueryFilterFfi {
    pub memberships: u32,
    pub filter: u32,
    pub exclude: Entity,
    pub sensors: bool,
}

impl From<QueryFilter> for QueryFilterFfi {
    fn from(f: QueryFilter) -> Self {
        Self {
            memberships: f.memberships,
            filter: f.filter,
            exclude: f.exclude.unwrap_or(Entity::from_bits(0)),
            sensors: f.sensors,
        }
    }
}

impl From<QueryFilterFfi> for QueryFilter {
    fn from(f: QueryFilterFfi) -> Self {
        Self {
            memberships: f.memberships,
            filter: f.filter,
            exclude: (f.exclude.to_bits() != 0).then_some(f.exclude),
            sensors: f.sensors,
        }
    }
}

/// The sweep of a shape cast: a direction (need not be normalised) and a length, metres.
#[repr(C)]
#[derive(abi_stable::StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct SweepFfi {
    pub direction: [f32; 3],
    pub max_distance: f32,
}

/// A [`CharacterMove`], as plain data.
#[repr(C)]
#[derive(abi_stable::StableAbi, Clone, Debug, PartialEq)]
pub struct CharacterMoveFfi {
    pub translation: [f32; 3],
    pub grounded: bool,
    pub collisions: RVec<RayHit>,
}

impl From<CharacterMove> for CharacterMoveFfi {
    fn from(m: CharacterMove) -> Self {
        Self {
            translation: m.translation.to_array(),
            grounded: m.grounded,
            collisions: m.collisions.into(),
        }
    }
}

impl From<CharacterMoveFfi> for CharacterMove {
    fn from(m: CharacterMoveFfi) -> Self {
        Self {
            translation: m.translation.into(),
            grounded: m.grounded,
            collisions: m.collisions.into_vec(),
        }
    }
}

/// A ray, as plain data.
#[repr(C)]
#[derive(abi_stable::StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct RayFfi {
    /// Start, world space.
    pub origin: [f32; 3],
    /// Direction (need not be normalised).
    pub direction: [f32; 3],
    /// Longest distance, metres.
    pub max_distance: f32,
}

/// What a plugin asks the host to do with plugins (after the frame).
#[repr(u8)]
#[derive(abi_stable::StableAbi, Clone, Copy, Debug, PartialEq, Eq)]
pub enum PluginOpFfi {
    /// Reload the plugin named by the argument.
    Reload,
    /// Reload every plugin loaded from a file.
    ReloadAll,
    /// Load the plugin given by the argument (a path or a NAME).
    Load,
    /// Unload the plugin named by the argument.
    Unload,
}

/// The host object handed to each plugin call, borrowed for that call only.
pub type HostRef<'a> = HostObject_TO<'a, abi_stable::sabi_types::RMut<'a, ()>>;

/// Adapts a safe [`HostServices`] to the [`HostObject`] vtable.
///
/// A panic inside the host's implementation must not unwind through `extern "C"` (that
/// aborts the process), so each call is guarded: a panicking host call is logged and
/// answered with an error or an empty value.
pub struct HostBridge<'h, H: ?Sized>(pub &'h mut H);

fn host_bug(what: &str) -> CtxErrorFfi {
    CtxError::Invalid {
        message: format!("the host panicked while serving `{what}` (a host bug)"),
    }
    .into()
}

fn guard<T>(what: &str, fallback: impl FnOnce() -> T, f: impl FnOnce() -> T) -> T {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(value) => value,
        Err(_) => {
            eprintln!("onyx: the host panicked while serving `{what}` to a plugin");
            fallback()
        }
    }
}

fn result<T>(what: &str, f: impl FnOnce() -> Result<T, CtxError>) -> RResult<T, CtxErrorFfi> {
    guard(
        what,
        || RResult::RErr(host_bug(what)),
        || f().map_err(Into::into).into(),
    )
}

impl<H: HostServices + ?Sized> HostObject for HostBridge<'_, H> {
    fn plugin_name(&self) -> RStr<'_> {
        self.0.plugin_name().into()
    }

    fn log(&mut self, level: LogLevel, message: RStr<'_>) {
        guard("log", || (), || self.0.log(level, message.as_str()))
    }

    fn time(&self) -> Time {
        guard("time", Time::default, || self.0.time())
    }

    fn input(&self) -> InputState {
        guard("input", InputState::default, || self.0.input())
    }

    fn request_quit(&mut self) {
        guard("request_quit", || (), || self.0.request_quit())
    }

    fn prevent_close(&mut self) {
        guard("prevent_close", || (), || self.0.prevent_close())
    }

    fn set_paused(&mut self, paused: bool) {
        guard("set_paused", || (), || self.0.set_paused(paused))
    }

    fn set_time_scale(&mut self, scale: f32) -> RResult<(), CtxErrorFfi> {
        result("set_time_scale", || self.0.set_time_scale(scale))
    }

    fn step_once(&mut self) {
        guard("step_once", || (), || self.0.step_once())
    }

    fn spawn(
        &mut self,
        builtins: RVec<BuiltinFfi>,
        blobs: RVec<BlobFfi>,
    ) -> RResult<Entity, CtxErrorFfi> {
        result("spawn", || {
            let builtins = builtins.into_iter().map(Into::into).collect();
            let blobs = blobs.into_iter().map(Into::into).collect();
            self.0.spawn(builtins, blobs)
        })
    }

    fn despawn(&mut self, entity: Entity) -> RResult<(), CtxErrorFfi> {
        result("despawn", || self.0.despawn(entity))
    }

    fn despawn_recursive(&mut self, entity: Entity) -> RResult<(), CtxErrorFfi> {
        result("despawn_recursive", || self.0.despawn_recursive(entity))
    }

    fn contains(&self, entity: Entity) -> bool {
        guard("contains", || false, || self.0.contains(entity))
    }

    fn set_parent(
        &mut self,
        entity: Entity,
        parent: Entity,
        keep: KeepPose,
    ) -> RResult<(), CtxErrorFfi> {
        let parent = (parent.to_bits() != 0).then_some(parent);
        result("set_parent", || self.0.set_parent(entity, parent, keep))
    }

    fn children(&mut self, entity: Entity) -> RResult<RVec<Entity>, CtxErrorFfi> {
        result("children", || self.0.children(entity).map(RVec::from))
    }

    fn world_pose(&mut self, entity: Entity) -> RResult<GlobalTransformFfi, CtxErrorFfi> {
        result("world_pose", || self.0.world_pose(entity).map(Into::into))
    }

    fn set_world_pose(&mut self, entity: Entity, pose: TransformFfi) -> RResult<(), CtxErrorFfi> {
        result("set_world_pose", || {
            self.0.set_world_pose(entity, pose.into())
        })
    }

    fn get_builtin(&mut self, entity: Entity, id: BuiltinId) -> RResult<BuiltinFfi, CtxErrorFfi> {
        result("get", || self.0.get_builtin(entity, id).map(Into::into))
    }

    fn set_builtin(&mut self, entity: Entity, value: BuiltinFfi) -> RResult<(), CtxErrorFfi> {
        result("set", || self.0.set_builtin(entity, value.into()))
    }

    fn remove_builtin(&mut self, entity: Entity, id: BuiltinId) -> RResult<(), CtxErrorFfi> {
        result("remove", || self.0.remove_builtin(entity, id))
    }

    fn get_blob(&mut self, entity: Entity, name: RStr<'_>) -> RResult<BlobFfi, CtxErrorFfi> {
        result("get", || {
            self.0.get_blob(entity, name.as_str()).map(Into::into)
        })
    }

    fn set_blob(&mut self, entity: Entity, blob: BlobFfi) -> RResult<(), CtxErrorFfi> {
        result("set", || self.0.set_blob(entity, blob.into()))
    }

    fn remove_blob(&mut self, entity: Entity, name: RStr<'_>) -> RResult<(), CtxErrorFfi> {
        result("remove", || self.0.remove_blob(entity, name.as_str()))
    }

    fn query_blobs(&mut self, name: RStr<'_>) -> RVec<EntityBlobFfi> {
        guard("query", RVec::new, || {
            self.0
                .query_blobs(name.as_str())
                .into_iter()
                .map(|(entity, blob)| EntityBlobFfi {
                    entity,
                    format: blob.format,
                    bytes: blob.bytes.into(),
                })
                .collect()
        })
    }

    // `entities` and `transforms` only refill a host-owned buffer; they are not guarded
    // because the borrow they return cannot leave a `catch_unwind` closure. They must not
    // panic (documented on `HostServices`).
    fn entities(&mut self) -> RSlice<'_, Entity> {
        self.0.entities().into()
    }

    fn transforms(&mut self) -> RSliceMut<'_, EntityTransform> {
        self.0.transforms().into()
    }

    fn commit_transforms(&mut self) -> RResult<(), CtxErrorFfi> {
        result("commit_transforms", || self.0.commit_transforms())
    }

    fn set_transforms(&mut self, items: RSlice<'_, EntityTransform>) -> RResult<(), CtxErrorFfi> {
        result("set_transforms", || self.0.set_transforms(items.as_slice()))
    }

    fn send(&mut self, name: RStr<'_>, payload: RSlice<'_, u8>) {
        guard(
            "send",
            || (),
            || self.0.send(name.as_str(), payload.as_slice()),
        )
    }

    fn request_plugin_op(&mut self, op: PluginOpFfi, argument: RStr<'_>) {
        let request = match op {
            PluginOpFfi::Reload => PluginRequest::Reload(argument.as_str().to_owned()),
            PluginOpFfi::ReloadAll => PluginRequest::ReloadAll,
            PluginOpFfi::Load => PluginRequest::Load(argument.as_str().to_owned()),
            PluginOpFfi::Unload => PluginRequest::Unload(argument.as_str().to_owned()),
        };
        guard("request_plugin", || (), || self.0.request_plugin(request))
    }

    fn load_mesh(&mut self, path: RStr<'_>) -> RResult<MeshId, CtxErrorFfi> {
        result("load_mesh", || self.0.load_mesh(path.as_str()))
    }

    fn load_texture(&mut self, path: RStr<'_>) -> RResult<TextureId, CtxErrorFfi> {
        result("load_texture", || self.0.load_texture(path.as_str()))
    }

    fn set_camera(&mut self, entity: Entity) -> RResult<(), CtxErrorFfi> {
        result("set_camera", || self.0.set_camera(entity))
    }

    fn draw_debug_lines(&mut self, lines: RSlice<'_, DebugLine>) {
        guard(
            "draw_debug_lines",
            || (),
            || self.0.draw_debug_lines(lines.as_slice()),
        )
    }

    fn physics_command(
        &mut self,
        entity: Entity,
        command: PhysicsCommand,
    ) -> RResult<(), CtxErrorFfi> {
        result("physics", || self.0.physics_command(entity, command))
    }

    fn raycast(&mut self, ray: RayFfi) -> ROption<RayHit> {
        guard(
            "raycast",
            || ROption::RNone,
            || {
                self.0
                    .raycast(ray.origin.into(), ray.direction.into(), ray.max_distance)
                    .into()
            },
        )
    }

    fn entity_list(&mut self) -> EntityListFfi {
        guard("entity_list", EntityListFfi::default, || {
            self.0.entity_list().into()
        })
    }

    fn host_report(&mut self, report: ReportFfi, argument: u64) -> RResult<RVec<u8>, CtxErrorFfi> {
        super::tool_bridge::host_report(&mut *self.0, report, argument)
    }

    fn components_of(&mut self, entity: Entity) -> RResult<ComponentsFfi, CtxErrorFfi> {
        result("components_of", || {
            let (builtins, blobs) = self.0.components_of(entity)?;
            Ok(ComponentsFfi {
                builtins: builtins.into_iter().map(Into::into).collect(),
                blobs: blobs.into_iter().map(Into::into).collect(),
            })
        })
    }

    fn scene_op(&mut self, op: SceneOpFfi, path: RStr<'_>) -> RResult<(), CtxErrorFfi> {
        result("scene", || match op {
            SceneOpFfi::New => self.0.new_scene(),
            SceneOpFfi::Open => self.0.open_scene(path.as_str()),
            SceneOpFfi::Save => self.0.save_scene(path.as_str()),
            SceneOpFfi::SaveCopy => self.0.save_scene_copy(path.as_str()),
            SceneOpFfi::Rename => {
                let path = path.as_str();
                self.0.set_scene_path((!path.is_empty()).then_some(path))
            }
        })
    }

    fn scene_path(&mut self) -> ROption<RString> {
        guard(
            "scene_path",
            || ROption::RNone,
            || self.0.scene_path().map(RString::from).into(),
        )
    }

    fn play_command(&mut self, command: PlayCommand) {
        guard("play", || (), || self.0.play_command(command))
    }

    fn play_mode(&self) -> PlayMode {
        guard("play_mode", PlayMode::default, || self.0.play_mode())
    }

    fn register_script(
        &mut self,
        name: RStr<'_>,
        default_params: RStr<'_>,
    ) -> RResult<(), CtxErrorFfi> {
        result("register_script", || {
            let params =
                serde_json::from_str(default_params.as_str()).map_err(|e| CtxError::Decode {
                    component: format!("default parameters of script `{}`", name.as_str()),
                    message: e.to_string(),
                })?;
            self.0.register_script(name.as_str(), params)
        })
    }

    fn screen_ray(&mut self, point: ScreenPointFfi) -> ROption<RayFfi> {
        let (at, size) = (point.at.into(), point.size.into());
        guard(
            "screen_ray",
            || ROption::RNone,
            || {
                self.0
                    .screen_ray(at, size)
                    .map(|ray| RayFfi {
                        origin: ray.origin.to_array(),
                        direction: ray.direction.to_array(),
                        max_distance: f32::INFINITY,
                    })
                    .into()
            },
        )
    }

    fn set_render_overrides(&mut self, overrides: RenderOverrides) {
        guard(
            "set_render_overrides",
            || (),
            || self.0.set_render_overrides(overrides),
        )
    }

    fn render_overrides(&self) -> RenderOverrides {
        guard("render_overrides", RenderOverrides::default, || {
            self.0.render_overrides()
        })
    }

    fn pick(&mut self, ray: RayFfi) -> ROption<RayHit> {
        guard(
            "pick",
            || ROption::RNone,
            || {
                self.0
                    .pick(ray.origin.into(), ray.direction.into(), ray.max_distance)
                    .into()
            },
        )
    }

    fn local_bounds(&mut self, entity: Entity) -> ROption<BoundsFfi> {
        guard(
            "local_bounds",
            || ROption::RNone,
            || {
                self.0
                    .local_bounds(entity)
                    .map(|b| BoundsFfi {
                        min: b.min.to_array(),
                        max: b.max.to_array(),
                    })
                    .into()
            },
        )
    }

    fn import_gltf(&mut self, path: RStr<'_>) -> RResult<Entity, CtxErrorFfi> {
        result("import_gltf", || self.0.import_gltf(path.as_str()))
    }

    fn overlap(
        &mut self,
        shape: ColliderShape,
        pose: TransformFfi,
        filter: QueryFilterFfi,
    ) -> RResult<RVec<Entity>, CtxErrorFfi> {
        result("overlap", || {
            self.0
                .overlap(shape, pose.into(), filter.into())
                .map(Into::into)
        })
    }

    fn shape_cast(
        &mut self,
        shape: ColliderShape,
        pose: TransformFfi,
        sweep: SweepFfi,
        filter: QueryFilterFfi,
    ) -> RResult<ROption<RayHit>, CtxErrorFfi> {
        result("shape_cast", || {
            self.0
                .shape_cast(
                    shape,
                    pose.into(),
                    sweep.direction.into(),
                    sweep.max_distance,
                    filter.into(),
                )
                .map(Into::into)
        })
    }

    fn joint_coordinate(&mut self, entity: Entity) -> RResult<ROption<f32>, CtxErrorFfi> {
        result("joint_coordinate", || {
            self.0.joint_coordinate(entity).map(Into::into)
        })
    }

    fn move_character(
        &mut self,
        entity: Entity,
        step: CharacterStepFfi,
    ) -> RResult<CharacterMoveFfi, CtxErrorFfi> {
        result("move_character", || {
            self.0
                .move_character(entity, step.desired.into(), &step.controller)
                .map(Into::into)
        })
    }
}

/// Lends `host` to `f` as a [`Ctx`](crate::Ctx), without crossing a library boundary: for
/// benchmarks that measure the boundary against a direct trait call.
pub fn with_ctx<H: HostServices + ?Sized, R>(
    host: &mut H,
    f: impl FnOnce(&mut crate::Ctx<'_>) -> R,
) -> R {
    let mut bridge = HostBridge(host);
    let host = HostObject_TO::from_ptr(&mut bridge, abi_stable::sabi_trait::TD_Opaque);
    let mut ctx = crate::Ctx::new(host);
    f(&mut ctx)
}
