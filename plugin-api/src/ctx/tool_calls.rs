//! The tool services on [`Ctx`]: world introspection, scenes, plugins, diagnostics, console,
//! play mode, scripts and the viewport. Any plugin may call them; the editor is built on them.

use serde::de::DeserializeOwned;
use serde::Serialize;

use super::{ok, Ctx};
use crate::__ffi::{ComponentOpFfi, ReportFfi, SceneOpFfi};
use crate::glam::Vec2;
use crate::host::PlayCommand;
use crate::tools::{
    ComponentEntry, Diagnostics, EntityList, LogLine, PlayMode, PluginInfo, Ray, RenderOverrides,
    ScriptInfo,
};
use crate::{CtxError, Entity};

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

    /// Every entity with its name (empty when unnamed), in one call: the hierarchy panel's
    /// source. Cheap for tens of thousands of entities.
    pub fn entity_list(&mut self) -> EntityList {
        self.host.entity_list().into()
    }

    /// Every component of `entity` — built-in (`Name`, `Transform`, `MeshRenderer`, `Camera`,
    /// `Light`, `RigidBody`, `Collider`) and plugin components (by their stored name,
    /// [`Script`](crate::Script) as `onyx.Script`) — with its value as JSON text.
    pub fn components_of(&mut self, entity: Entity) -> Result<Vec<ComponentEntry>, CtxError> {
        self.report(ReportFfi::Components, entity.to_bits())
    }

    /// Writes component `type_name` of `entity` from JSON text (the form
    /// [`Ctx::components_of`] gives). The value is checked like any write: a NaN, infinity,
    /// unknown field or wrong type is refused with an error saying what, and nothing changes.
    pub fn set_component_json(
        &mut self,
        entity: Entity,
        type_name: &str,
        json: &str,
    ) -> Result<(), CtxError> {
        ok(self
            .host
            .edit_component(entity, ComponentOpFfi::Set, type_name.into(), json.into()))
    }

    /// [`Ctx::set_component_json`] from any serde value.
    pub fn set_component_value(
        &mut self,
        entity: Entity,
        type_name: &str,
        value: &impl Serialize,
    ) -> Result<(), CtxError> {
        let json = serde_json::to_string(value).map_err(|e| CtxError::Encode {
            component: type_name.to_owned(),
            message: e.to_string(),
        })?;
        self.set_component_json(entity, type_name, &json)
    }

    /// Adds the built-in component `type_name` (or `onyx.Script`) with its default value.
    pub fn add_component(&mut self, entity: Entity, type_name: &str) -> Result<(), CtxError> {
        ok(self.host.edit_component(
            entity,
            ComponentOpFfi::AddDefault,
            type_name.into(),
            "".into(),
        ))
    }

    /// Removes component `type_name` (built-in or plugin) from `entity`.
    pub fn remove_component(&mut self, entity: Entity, type_name: &str) -> Result<(), CtxError> {
        ok(self
            .host
            .edit_component(entity, ComponentOpFfi::Remove, type_name.into(), "".into()))
    }

    // ----- scenes -----

    /// Replaces the world with an empty one (plugins keep running; entity handles they hold
    /// become stale).
    pub fn new_scene(&mut self) -> Result<(), CtxError> {
        ok(self.host.scene_op(SceneOpFfi::New, "".into()))
    }

    /// Replaces the world with the scene file at `path`. A missing or malformed file gives
    /// an error naming the line and column, and leaves the world untouched.
    pub fn open_scene(&mut self, path: &str) -> Result<(), CtxError> {
        ok(self.host.scene_op(SceneOpFfi::Open, path.into()))
    }

    /// Saves the world to `path` atomically (a crash never leaves half a file).
    pub fn save_scene(&mut self, path: &str) -> Result<(), CtxError> {
        ok(self.host.scene_op(SceneOpFfi::Save, path.into()))
    }

    /// The scene file the world was last opened from or saved to (`None` for a new world).
    pub fn scene_path(&mut self) -> Option<String> {
        self.host.scene_path().into_option().map(Into::into)
    }

    // ----- plugins, diagnostics, console -----

    /// The loaded plugins, in call order, with their state (running, or faulted and why).
    pub fn plugins(&mut self) -> Vec<PluginInfo> {
        self.report(ReportFfi::Plugins, 0).unwrap_or_default()
    }

    /// Figures of the last complete frame: frame time, fixed steps, physics, rendering and
    /// the time spent in each plugin per lifecycle method.
    pub fn diagnostics(&mut self) -> Diagnostics {
        self.report(ReportFfi::Diagnostics, 0).unwrap_or_default()
    }

    /// Console lines logged after line `seq` (0 for everything still kept), oldest first.
    /// Pass the last line's [`LogLine::seq`] next time to read incrementally.
    pub fn log_lines_since(&mut self, seq: u64) -> Vec<LogLine> {
        self.report(ReportFfi::LogLines, seq).unwrap_or_default()
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
    pub fn registered_scripts(&mut self) -> Vec<ScriptInfo> {
        self.report(ReportFfi::Scripts, 0).unwrap_or_default()
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
}
