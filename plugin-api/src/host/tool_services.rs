//! [`ToolServices`]: the host services tools (the editor first) use — world introspection,
//! scenes, plugins, diagnostics, console, play mode, scripts, viewport — in plain Rust.

use crate::glam::{Vec2, Vec3};
use crate::host::{Blob, PlayCommand};
use crate::tools::{
    Bounds, Diagnostics, EntityList, LogLine, PlayMode, PluginInfo, Ray, RenderOverrides,
    ScriptInfo,
};
use crate::{BuiltinValue, CtxError, Entity, RayHit};

fn unsupported(service: &str) -> CtxError {
    CtxError::Unsupported {
        service: service.to_owned(),
    }
}

/// The tool half of the services behind [`Ctx`](crate::Ctx). Every method has a default
/// (an error or an empty answer), so a host that serves only the basics implements nothing.
/// Implementations must not panic.
#[allow(unused_variables)]
pub trait ToolServices {
    /// Every entity with its name and parent.
    fn entity_list(&mut self) -> EntityList {
        EntityList::default()
    }
    /// Every component of `entity`: the built-ins in list order, then the plugin components
    /// by name.
    fn components_of(
        &mut self,
        entity: Entity,
    ) -> Result<(Vec<BuiltinValue>, Vec<Blob>), CtxError> {
        Err(unsupported("components_of"))
    }
    /// Replaces the world with an empty one.
    fn new_scene(&mut self) -> Result<(), CtxError> {
        Err(unsupported("new_scene"))
    }
    /// Replaces the world with the scene file at `path` (untouched on error).
    fn open_scene(&mut self, path: &str) -> Result<(), CtxError> {
        Err(unsupported("open_scene"))
    }
    /// Saves the world to `path`, atomically.
    fn save_scene(&mut self, path: &str) -> Result<(), CtxError> {
        Err(unsupported("save_scene"))
    }
    /// Saves the world to `path`, atomically, without making it the world's file.
    fn save_scene_copy(&mut self, path: &str) -> Result<(), CtxError> {
        Err(unsupported("save_scene_copy"))
    }
    /// The file the world was last opened from or saved to.
    fn scene_path(&mut self) -> Option<String> {
        None
    }
    /// Names the file the world belongs to (`None`: an untitled world).
    fn set_scene_path(&mut self, path: Option<&str>) -> Result<(), CtxError> {
        Err(unsupported("set_scene_path"))
    }
    /// The loaded plugins.
    fn plugin_infos(&mut self) -> Vec<PluginInfo> {
        Vec::new()
    }
    /// Figures of the last frame.
    fn diagnostics(&mut self) -> Diagnostics {
        Diagnostics::default()
    }
    /// Console lines with a sequence number above `seq`.
    fn log_lines_since(&mut self, seq: u64) -> Vec<LogLine> {
        Vec::new()
    }
    /// Changes the play session.
    fn play_command(&mut self, command: PlayCommand) {}
    /// The play session's state.
    fn play_mode(&self) -> PlayMode {
        PlayMode::Playing
    }
    /// Registers script `name`, run by the calling plugin.
    fn register_script(
        &mut self,
        name: &str,
        default_params: serde_json::Value,
    ) -> Result<(), CtxError> {
        Err(unsupported("register_script"))
    }
    /// Every registered script.
    fn registered_scripts(&mut self) -> Vec<ScriptInfo> {
        Vec::new()
    }
    /// The ray through `point` (pixels from the top left) of a `size`-pixel view of the
    /// active camera.
    fn screen_ray(&mut self, point: Vec2, size: Vec2) -> Option<Ray> {
        None
    }
    /// Sets the view switches.
    fn set_render_overrides(&mut self, overrides: RenderOverrides) {}
    /// The view switches.
    fn render_overrides(&self) -> RenderOverrides {
        RenderOverrides::default()
    }
    /// The nearest entity whose shape the ray from `origin` along `direction` (unit length)
    /// meets within `max_distance` metres: visible meshes and colliders, at their world
    /// poses, in every play mode.
    fn pick(&mut self, origin: Vec3, direction: Vec3, max_distance: f32) -> Option<RayHit> {
        None
    }
    /// The box around what `entity` shows (its mesh, else its collider), in its own frame.
    fn local_bounds(&mut self, entity: Entity) -> Option<Bounds> {
        None
    }
}
