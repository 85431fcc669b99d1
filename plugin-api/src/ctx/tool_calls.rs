//! The tool services on [`Ctx`]: world introspection, scenes, plugins, diagnostics, console,
//! play mode, scripts and the viewport. Any plugin may call them; the editor is built on them.

use serde::de::DeserializeOwned;
use serde::Serialize;

use super::{ok, Ctx};
use crate::__ffi::{ReportFfi, SceneOpFfi};
use crate::glam::{Vec2, Vec3};
use crate::host::PlayCommand;
use crate::tools::{
    Bounds, ComponentKey, ComponentValue, Diagnostics, EntityList, LogLine, PlayMode, PluginInfo,
    PluginValue, Ray, RenderOverrides, ScriptInfo,
};
use crate::{BlobFormat, BuiltinValue, CtxError, Entity, RayHit};

impl Ctx<'_> {
    fn report<T: DeserializeOwned>(
        &mut self,
        report: ReportFfi,
        argument: u64,
    ) -> Result<T, CtxError> {
        let bytes = ok(self.host.host_report(report, argument))?;
        serde_json::from_slice(&bytes).map_err(|e| CtxError::Decode {
            component: format!("{report:?} report"),
            message: e.to_string(),
        })
    }

    // ----- world introspection -----

    /// Every entity with its name (empty when unnamed) and its parent, in one call: the
    /// hierarchy panel's source. Cheap for tens of thousands of entities.
    pub fn entity_list(&mut self) -> EntityList {
        self.host.entity_list().into()
    }

    /// Every component of `entity`, typed: the built-ins (in the order of
    /// [`BuiltinId::ALL`](crate::BuiltinId::ALL)), then plugin components by name
    /// ([`Script`](crate::Script) as `onyx.Script`). A plugin component stored by serde
    /// whose bytes are not JSON is an error naming it, never an empty value.
    pub fn components_of(&mut self, entity: Entity) -> Result<Vec<ComponentValue>, CtxError> {
        let answer = ok(self.host.components_of(entity))?;
        let mut values: Vec<ComponentValue> = answer
            .builtins
            .into_iter()
            .map(|b| ComponentValue::Builtin(BuiltinValue::from(b)))
            .collect();
        for blob in answer.blobs {
            let name = blob.name.into_string();
            let value = match blob.format {
                BlobFormat::Json => {
                    PluginValue::Json(serde_json::from_slice(&blob.bytes).map_err(|e| {
                        CtxError::Decode {
                            component: name.clone(),
                            message: e.to_string(),
                        }
                    })?)
                }
                BlobFormat::Raw => PluginValue::Raw(blob.bytes.into_vec()),
            };
            values.push(ComponentValue::Plugin { name, value });
        }
        Ok(values)
    }

    /// Writes one component of `entity` (a built-in, or a plugin component by name), checked
    /// like every write: a NaN, infinity or out-of-range field is refused with an error
    /// naming it, and nothing changes.
    pub fn set_component(&mut self, entity: Entity, value: ComponentValue) -> Result<(), CtxError> {
        match value {
            ComponentValue::Builtin(value) => self.set_builtin(entity, value),
            ComponentValue::Plugin {
                name,
                value: PluginValue::Json(json),
            } => {
                let bytes = serde_json::to_vec(&json).map_err(|e| CtxError::Encode {
                    component: name.clone(),
                    message: e.to_string(),
                })?;
                self.raw_set_blob(entity, &name, BlobFormat::Json, bytes.into())
            }
            ComponentValue::Plugin {
                name,
                value: PluginValue::Raw(bytes),
            } => self.raw_set_blob(entity, &name, BlobFormat::Raw, bytes.into()),
        }
    }

    /// Removes one component (a built-in, or a plugin component by name) from `entity`.
    pub fn remove_component(&mut self, entity: Entity, key: &ComponentKey) -> Result<(), CtxError> {
        match key {
            ComponentKey::Builtin(id) => self.remove_builtin(entity, *id),
            ComponentKey::Plugin(name) => self.raw_remove_blob(entity, name),
        }
    }

    // ----- scenes -----

    /// Replaces the world with an empty one (plugins keep running; entity handles they hold
    /// become stale).
    pub fn new_scene(&mut self) -> Result<(), CtxError> {
        ok(self.host.scene_op(SceneOpFfi::New, "".into()))
    }

    /// Replaces the world with the scene file at `path`. A missing or malformed file gives
    /// [`CtxError::Scene`] naming the file, line and column, and leaves the world untouched.
    pub fn open_scene(&mut self, path: &str) -> Result<(), CtxError> {
        ok(self.host.scene_op(SceneOpFfi::Open, path.into()))
    }

    /// Saves the world to `path` atomically (a crash never leaves half a file).
    pub fn save_scene(&mut self, path: &str) -> Result<(), CtxError> {
        ok(self.host.scene_op(SceneOpFfi::Save, path.into()))
    }

    /// Saves the world to `path` atomically, leaving [`Ctx::scene_path`] as it is: an
    /// autosave, a backup or an export, not a "Save As".
    pub fn save_scene_copy(&mut self, path: &str) -> Result<(), CtxError> {
        ok(self.host.scene_op(SceneOpFfi::SaveCopy, path.into()))
    }

    /// The scene file the world was last opened from or saved to (`None` for a new world).
    pub fn scene_path(&mut self) -> Option<String> {
        self.host.scene_path().into_option().map(Into::into)
    }

    /// Names the file the world belongs to without reading or writing it (`None`: an
    /// untitled world): a world restored from a recovery copy is named after the scene it
    /// was a copy of, so that Save writes there.
    pub fn set_scene_path(&mut self, path: Option<&str>) -> Result<(), CtxError> {
        ok(self
            .host
            .scene_op(SceneOpFfi::Rename, path.unwrap_or_default().into()))
    }

    // ----- plugins, diagnostics, console -----

    /// The loaded plugins, in call order, with their state (running, or faulted and why).
    pub fn plugins(&mut self) -> Result<Vec<PluginInfo>, CtxError> {
        self.report(ReportFfi::Plugins, 0)
    }

    /// Figures of the last complete frame: frame time, fixed steps, physics, rendering and
    /// the time spent in each plugin per lifecycle method.
    pub fn diagnostics(&mut self) -> Result<Diagnostics, CtxError> {
        self.report(ReportFfi::Diagnostics, 0)
    }

    /// Console lines logged after line `seq` (0 for everything still kept), oldest first.
    /// Pass the last line's [`LogLine::seq`] next time to read incrementally.
    pub fn log_lines_since(&mut self, seq: u64) -> Result<Vec<LogLine>, CtxError> {
        self.report(ReportFfi::LogLines, seq)
    }

    // ----- play mode -----

    /// Starts playing: from Edit, the world is snapshot first (see [`Ctx::stop`]); from
    /// Paused, resumes.
    pub fn play(&mut self) {
        self.host.play_command(PlayCommand::Play)
    }

    /// Pauses the play session (no fixed steps, no script updates).
    pub fn pause(&mut self) {
        self.host.play_command(PlayCommand::Pause)
    }

    /// Runs exactly one fixed step next frame and stays paused.
    pub fn step(&mut self) {
        self.host.play_command(PlayCommand::Step)
    }

    /// Ends the play session and puts the world back exactly as it was at [`Ctx::play`]
    /// (entities, their handles, plugin components, physics). Also enters Edit mode from a
    /// host that started playing.
    pub fn stop(&mut self) {
        self.host.play_command(PlayCommand::Stop)
    }

    /// Edit, Playing or Paused.
    pub fn play_mode(&self) -> PlayMode {
        self.host.play_mode()
    }

    // ----- scripts -----

    /// Registers the behaviour `name`, run by this plugin's
    /// [`Plugin::on_script`](crate::Plugin::on_script) for every entity whose
    /// [`Script`](crate::Script) names it. `default_params` start new scripts of this kind.
    /// Call it in `on_attach` (it is asked again after a hot reload).
    pub fn register_script(
        &mut self,
        name: &str,
        default_params: &impl Serialize,
    ) -> Result<(), CtxError> {
        let params = serde_json::to_string(default_params).map_err(|e| CtxError::Encode {
            component: format!("default parameters of script `{name}`"),
            message: e.to_string(),
        })?;
        ok(self
            .host
            .register_script(name.into(), params.as_str().into()))
    }

    /// Every registered script (the inspector's drop-down).
    pub fn registered_scripts(&mut self) -> Result<Vec<ScriptInfo>, CtxError> {
        self.report(ReportFfi::Scripts, 0)
    }

    // ----- viewport -----

    /// The ray through `point` (pixels from the top-left corner) of a view `size` pixels
    /// large, seen through the active camera: click-to-select is
    /// `ctx.screen_ray(p, size).and_then(|r| ctx.raycast(r.origin, r.direction, 1000.0))`.
    /// `None` for a point outside the view or an empty view.
    pub fn screen_ray(&mut self, point: Vec2, size: Vec2) -> Option<Ray> {
        let ray = self
            .host
            .screen_ray(crate::__ffi::ScreenPointFfi {
                at: point.to_array(),
                size: size.to_array(),
            })
            .into_option()?;
        Some(Ray {
            origin: ray.origin.into(),
            direction: ray.direction.into(),
        })
    }

    /// Sets the view switches (grid, physics debug drawing, shading of the whole view).
    pub fn set_render_overrides(&mut self, overrides: RenderOverrides) {
        self.host.set_render_overrides(overrides)
    }

    /// The view switches in effect.
    pub fn render_overrides(&self) -> RenderOverrides {
        self.host.render_overrides()
    }

    /// The nearest entity the ray from `origin` along `direction` meets within
    /// `max_distance` metres, by what it shows: each visible mesh (the built-in shapes
    /// exactly, a loaded model by its bounding box) and each collider, at its world pose —
    /// children too — in Edit mode as well as while playing (no physics step needed, unlike
    /// [`Ctx::raycast`], which sees only simulated colliders). Click-to-select is
    /// `ctx.screen_ray(p, size).and_then(|r| ctx.pick(r.origin, r.direction, 1000.0))`.
    pub fn pick(&mut self, origin: Vec3, direction: Vec3, max_distance: f32) -> Option<RayHit> {
        let ray = crate::__ffi::RayFfi {
            origin: origin.to_array(),
            direction: direction.to_array(),
            max_distance,
        };
        self.host.pick(ray).into_option()
    }

    /// The box around what `entity` shows — its mesh (a loaded model's bounding box), else
    /// its collider — in its own frame: place its corners with [`Ctx::world_pose`] to outline
    /// it. `None` for an entity that shows nothing, or does not exist.
    pub fn local_bounds(&mut self, entity: Entity) -> Option<Bounds> {
        let bounds = self.host.local_bounds(entity).into_option()?;
        Some(Bounds {
            min: bounds.min.into(),
            max: bounds.max.into(),
        })
    }
}
