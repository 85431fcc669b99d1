//! [`Plugin`]: the trait a plugin implements, and [`AttachInfo`].

use crate::{Ctx, Event, Flow};

/// An error a plugin returns from [`Plugin::on_attach`] or the state methods.
pub type PluginError = Box<dyn std::error::Error + Send + Sync + 'static>;

/// An Onyx plugin. Implement the methods you need (all have empty defaults) and export the
/// type with [`export_plugin!`](crate::export_plugin).
///
/// The host calls, in this order:
///
/// 1. `on_attach` once when the plugin is loaded (or reloaded: see [`AttachInfo::reload`]);
/// 2. `on_init` once, after every plugin given at start-up is attached;
/// 3. each frame: `on_event` for each pending event, `on_fixed_update` 0..N times (one per
///    fixed step), `on_update` once, `on_script` for each entity running a script this
///    plugin registered (while playing), `on_render` once, `draw_gui` once (only if
///    overridden);
///    `on_resize` when the window changes size;
/// 4. `on_detach` once, when the host quits or unloads the plugin.
///
/// A panic in any method is caught at the boundary: the plugin is marked *faulted*, reported,
/// and never called again, while the host and other plugins go on.
#[allow(unused_variables)]
pub trait Plugin: Send + 'static {
    /// The plugin was loaded. Return an error to refuse to start (the plugin is then faulted).
    fn on_attach(&mut self, ctx: &mut Ctx, info: &AttachInfo) -> Result<(), PluginError> {
        Ok(())
    }

    /// Every start-up plugin is attached; plugins loaded later get this right after `on_attach`.
    fn on_init(&mut self, ctx: &mut Ctx) {}

    /// An event from the window, input, the host, or another plugin.
    fn on_event(&mut self, ctx: &mut Ctx, event: &Event) {}

    /// One fixed simulation step of [`Time::fixed_delta`](crate::Time::fixed_delta) seconds.
    fn on_fixed_update(&mut self, ctx: &mut Ctx) {}

    /// Once per frame, after the fixed steps; `dt` is the frame's scaled time in seconds.
    fn on_update(&mut self, ctx: &mut Ctx, dt: f32) -> Flow {
        Flow::Continue
    }

    /// Once per frame, after `on_update`: submit what to draw.
    fn on_render(&mut self, ctx: &mut Ctx) {}

    /// Once per frame, after `on_render`: draw user interface with [egui](crate::egui) into
    /// `ui`, the root of the whole window (use `ui.ctx()` for floating windows). The plugin
    /// has its own egui context; what it draws is rendered over the scene, and input its UI
    /// takes (pointer over its areas, keys while a text field has focus) does not reach the
    /// scene. Show the scene inside the UI with [`gui::viewport`](crate::gui::viewport).
    ///
    /// ```
    /// use onyx_plugin_api::{egui, Ctx, Name, Plugin, Transform};
    ///
    /// struct Spawner;
    /// impl Plugin for Spawner {
    ///     fn draw_gui(&mut self, ctx: &mut Ctx, ui: &mut egui::Ui) {
    ///         egui::Window::new("Tools").show(ui.ctx(), |ui| {
    ///             if ui.button("Spawn").clicked() {
    ///                 ctx.spawn((Name::new("box"), Transform::IDENTITY)).ok();
    ///             }
    ///         });
    ///     }
    /// }
    /// ```
    ///
    /// A plugin that keeps this default costs nothing per frame: no egui runs for it.
    fn draw_gui(&mut self, ctx: &mut Ctx, ui: &mut egui::Ui) {
        crate::__ffi::mark_no_gui();
    }

    /// A script this plugin registered ([`Ctx::register_script`]) runs on an entity: once
    /// `Created`, each frame `Update` while playing, and `Destroyed` at the end. See
    /// [`ScriptCall`](crate::ScriptCall).
    fn on_script(&mut self, ctx: &mut Ctx, call: &crate::ScriptCall) {}

    /// The window's drawable area changed to `width` × `height` physical pixels.
    fn on_resize(&mut self, ctx: &mut Ctx, width: u32, height: u32) {}

    /// The plugin is being unloaded (the host quits, or a reload replaces it).
    fn on_detach(&mut self, ctx: &mut Ctx) {}

    /// Serializes the plugin's own fields before a hot reload (see [`crate::state`]).
    /// Entities and components live in the host and need no saving.
    fn save_state(&self) -> Result<Vec<u8>, PluginError> {
        Ok(Vec::new())
    }

    /// Restores what [`Plugin::save_state`] wrote, before `on_attach` of the new build.
    fn load_state(&mut self, state: &[u8]) -> Result<(), PluginError> {
        Ok(())
    }
}

/// What the host tells a plugin when attaching it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct AttachInfo {
    /// `true` when this attach replaces an earlier build of the same plugin (hot reload):
    /// the world already holds the entities the plugin made before.
    pub reload: bool,
    /// Settings given to the plugin by the user (`onyx run --set NAME.KEY=VALUE`), in order.
    pub settings: Vec<(String, String)>,
}

impl AttachInfo {
    /// The last value given for `key`, if any.
    pub fn setting(&self, key: &str) -> Option<&str> {
        self.settings
            .iter()
            .rev()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }

    /// The setting `key` parsed as a `T`: `None` if absent, an error naming the key if it
    /// does not parse.
    pub fn parse_setting<T>(&self, key: &str) -> Result<Option<T>, PluginError>
    where
        T: std::str::FromStr,
        T::Err: std::fmt::Display,
    {
        match self.setting(key) {
            None => Ok(None),
            Some(text) => text
                .parse()
                .map(Some)
                .map_err(|e| format!("setting `{key}` = `{text}` is not valid: {e}").into()),
        }
    }
}

impl From<crate::__ffi::AttachInfoFfi<'_>> for AttachInfo {
    fn from(info: crate::__ffi::AttachInfoFfi<'_>) -> Self {
        Self {
            reload: info.reload,
            settings: info
                .settings
                .iter()
                .map(|pair| (pair.0.as_str().to_owned(), pair.1.as_str().to_owned()))
                .collect(),
        }
    }
}
