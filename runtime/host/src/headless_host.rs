//! [`HeadlessHost`]: a host with no window and no GPU, for tests and batch runs.

use std::path::Path;

use onyx_plugin_api::{
    egui, Entity, Event, InputEvent, Key, MouseButton, Name, Plugin, WindowEvent,
};

use crate::entity_id::to_api;
use crate::plugins::{PluginLoadError, PluginStatus};
use crate::scene::SceneError;
use crate::{FrameReport, Host, HostConfig};

/// A [`Host`] stepped by hand with a fixed frame time (one fixed step per frame by default),
/// so runs are deterministic. Creating one installs the console's `tracing` layer when no
/// global subscriber is set, so `Ctx::log_lines_since` works in tests.
///
/// ```
/// use onyx_runtime::HeadlessHost;
/// use onyx_plugin_api::{Ctx, Name, Plugin, Transform};
///
/// #[derive(Default)]
/// struct Spawner;
/// impl Plugin for Spawner {
///     fn on_init(&mut self, ctx: &mut Ctx) {
///         ctx.spawn((Name::new("box"), Transform::from_xyz(0.0, 1.0, 0.0))).unwrap();
///     }
/// }
///
/// let mut host = HeadlessHost::new();
/// host.add_plugin("spawner", Spawner).unwrap();
/// host.step(3);
/// assert!(host.find::<Transform>("box").is_some());
/// ```
pub struct HeadlessHost {
    host: Host,
    frame_time: f64,
    render: Option<crate::render::RenderSystem>,
    render_settings: onyx_render::RenderSettings,
}

impl Default for HeadlessHost {
    fn default() -> Self {
        Self::new()
    }
}

impl HeadlessHost {
    /// A headless host with the default configuration (60 Hz).
    pub fn new() -> Self {
        Self::with_config(HostConfig::default())
    }

    /// A headless host with `config`; each frame lasts one fixed step.
    pub fn with_config(config: HostConfig) -> Self {
        crate::console::install_default();
        let mut host = Host::new(config);
        // Tests find widgets by label: plugins build their AccessKit tree.
        host.gui_mut().set_accesskit(true);
        let frame_time = host.clock_ref_fixed_delta();
        Self {
            host,
            frame_time,
            render: None,
            render_settings: crate::render::RenderSystem::offscreen_settings(),
        }
    }

    /// Sets the simulated duration of each frame, seconds.
    pub fn set_frame_time(&mut self, seconds: f64) {
        self.frame_time = seconds;
    }

    /// Adds an in-process plugin (through the same ABI adapter as a library).
    pub fn add_plugin<P: Plugin>(
        &mut self,
        name: &'static str,
        plugin: P,
    ) -> Result<(), PluginLoadError> {
        self.host.add_plugin(name, plugin)
    }

    /// Loads a plugin by library path or NAME. Returns its name.
    pub fn load_plugin(&mut self, spec: &str) -> Result<String, PluginLoadError> {
        self.host.load_plugin(spec)
    }

    /// Loads the plugin library at `path`. Returns its name.
    pub fn load_plugin_file(&mut self, path: &Path) -> Result<String, PluginLoadError> {
        self.host.load_plugin_file(path)
    }

    /// Spawns the entities of a scene file.
    pub fn load_scene(&mut self, path: &Path) -> Result<usize, SceneError> {
        self.host.load_scene(path)
    }

    /// Runs up to `frames` frames, stopping after a frame in which quit was requested.
    /// Returns the number of frames run.
    pub fn step(&mut self, frames: u32) -> u32 {
        for n in 0..frames {
            if self.host.frame(self.frame_time).quit {
                return n + 1;
            }
        }
        frames
    }

    /// Runs one frame that lasted `seconds`.
    pub fn step_with(&mut self, seconds: f64) -> FrameReport {
        self.host.frame(seconds)
    }

    /// Queues an event (input, window, custom…) for the next frame.
    pub fn inject(&mut self, event: impl Into<Event>) {
        self.host.push_event(event);
    }

    /// The world.
    pub fn world(&self) -> &hecs::World {
        self.host.world()
    }

    /// The first entity named `name` that has a `T`, with a copy of it.
    pub fn find<T: hecs::Component + Clone>(&self, name: &str) -> Option<(Entity, T)> {
        let mut query = self.host.world().query::<(hecs::Entity, &Name, &T)>();
        let found = query
            .iter()
            .filter(|(_, n, _)| n.as_str() == name)
            .min_by_key(|(e, _, _)| e.to_bits())
            .map(|(e, _, value)| (to_api(e), value.clone()));
        found
    }

    /// A copy of `entity`'s `T`.
    pub fn get<T: hecs::Component + Clone>(&self, entity: Entity) -> Option<T> {
        let e = crate::entity_id::to_hecs(entity)?;
        self.host.world().get::<&T>(e).ok().map(|v| (*v).clone())
    }

    /// The status of plugin `name`.
    pub fn plugin_status(&self, name: &str) -> Option<&PluginStatus> {
        self.host.plugin(name).map(|p| p.status())
    }

    /// Whether a plugin asked to quit.
    pub fn quit_requested(&self) -> bool {
        self.host.quit_requested()
    }

    /// The state as JSON, as `onyx run --dump-state` writes it.
    pub fn dump_state(&self) -> serde_json::Value {
        self.host.dump_state()
    }

    /// The host inside.
    pub fn host(&self) -> &Host {
        &self.host
    }

    /// The host inside, mutably.
    pub fn host_mut(&mut self) -> &mut Host {
        &mut self.host
    }

    /// Sets the renderer settings used from the next renderer created (before the first
    /// [`HeadlessHost::screenshot`]). Default: deterministic (MSAA off), shaders from the
    /// source checkout's `shaders/` folder when there is one.
    pub fn set_render_settings(&mut self, settings: onyx_render::RenderSettings) {
        self.render_settings = settings;
    }

    /// Draws the world offscreen into a `width` × `height` image, creating a renderer on the
    /// first call (on the adapter the environment names; Mesa's CPU Vulkan driver works).
    /// Deterministic settings: MSAA off, so the same scene gives the same pixels.
    pub fn screenshot(
        &mut self,
        width: u32,
        height: u32,
    ) -> Result<onyx_render::image::RgbaImage, crate::render::ScreenshotError> {
        let system = match &mut self.render {
            Some(system) => system,
            None => {
                let settings = self.render_settings.clone();
                let mut system = crate::render::RenderSystem::new_headless(settings)?;
                if let Err(error) = system.watch_shaders() {
                    tracing::warn!("shader changes will not be picked up: {error}");
                }
                if let Err(error) = system.watch_assets() {
                    tracing::warn!("model and texture changes will not be picked up: {error}");
                }
                self.render.insert(system)
            }
        };
        self.host.render_image(system, width, height)
    }

    // ----- GUI -----

    /// Sets the size of the pretend window the plugins' GUIs lay out in, pixels (default
    /// 1280 × 720; a screenshot of another size shows the top-left part). Plugins get a
    /// resize event at the next frame.
    pub fn set_window_size(&mut self, width: u32, height: u32) {
        self.host.push_event(WindowEvent::Resized { width, height });
    }

    /// Queues the pointer moving to `pos` (GUI points; pixels at the headless scale of 1).
    pub fn pointer_move(&mut self, pos: egui::Pos2) {
        let scale = self.host.gui().input().pixels_per_point();
        self.host.push_event(InputEvent::CursorMoved {
            x: pos.x * scale,
            y: pos.y * scale,
        });
    }

    /// Clicks the left button at `pos` (GUI points) as a person would: moves there, presses,
    /// releases, one frame each (3 frames).
    pub fn click_at(&mut self, pos: egui::Pos2) {
        self.pointer_move(pos);
        self.step(1);
        for pressed in [true, false] {
            self.host.push_event(InputEvent::MouseButton {
                button: MouseButton::Left,
                pressed,
            });
            self.step(1);
        }
    }

    /// Drags with the left button from `from` to `to` (GUI points) as a person would: moves
    /// there, presses, moves in `steps` equal moves (a frame each), releases.
    pub fn drag(&mut self, from: egui::Pos2, to: egui::Pos2, steps: u32) {
        self.pointer_move(from);
        self.step(1);
        self.host.push_event(InputEvent::MouseButton {
            button: MouseButton::Left,
            pressed: true,
        });
        self.step(1);
        let steps = steps.max(1);
        for i in 1..=steps {
            self.pointer_move(from + (to - from) * (i as f32 / steps as f32));
            self.step(1);
        }
        self.host.push_event(InputEvent::MouseButton {
            button: MouseButton::Left,
            pressed: false,
        });
        self.step(1);
    }

    /// Presses (`true`) or releases mouse `button` and leaves it so: for a button held while
    /// keys are pressed (the editor's fly camera: right button + WASD).
    pub fn hold_button(&mut self, button: MouseButton, down: bool) {
        self.host.push_event(InputEvent::MouseButton {
            button,
            pressed: down,
        });
    }

    /// Scrolls the wheel by `lines` (positive: away from the user).
    pub fn scroll(&mut self, lines: f32) {
        self.host
            .push_event(InputEvent::Scroll { dx: 0.0, dy: lines });
    }

    /// Presses (`true`) or releases `key` and leaves it so: for a modifier held through a
    /// click or a drag.
    pub fn hold_key(&mut self, key: Key, down: bool) {
        self.host.push_event(InputEvent::Key {
            key,
            pressed: down,
            repeat: false,
        });
    }

    /// Clicks the centre of the widget labelled `label` (see [`HeadlessHost::find_widget`]).
    /// Returns `false`, clicking nothing, when no plugin shows such a widget.
    pub fn click_widget(&mut self, label: &str) -> bool {
        match self.find_widget(label) {
            Some(rect) => {
                self.click_at(rect.center());
                true
            }
            None => false,
        }
    }

    /// Presses and releases `key` (one frame later the UI has seen both).
    pub fn press_key(&mut self, key: Key) {
        for pressed in [true, false] {
            self.host.push_event(InputEvent::Key {
                key,
                pressed,
                repeat: false,
            });
        }
    }

    /// Types `text` (into the focused text field, if a plugin's UI has one).
    pub fn type_text(&mut self, text: &str) {
        self.host.push_event(InputEvent::Text(text.to_owned()));
    }

    /// The screen rectangle (GUI points) of the widget labelled `label` — a button's text,
    /// a label's text, a window's title — in the topmost plugin UI that shows one, as of
    /// the last frame. Like `egui_kittest`, through the UI's AccessKit tree.
    pub fn find_widget(&self, label: &str) -> Option<egui::Rect> {
        self.find_widgets(label).first().copied()
    }

    /// Every widget labelled `label` in the topmost plugin UI that shows any, in tree order —
    /// for when a label is on the screen twice (a tab and the menu entry that hides it).
    pub fn find_widgets(&self, label: &str) -> Vec<egui::Rect> {
        self.host.find_widgets(label)
    }

    /// The first widget whose label (or text) contains `text`: a log line, a status message.
    pub fn find_widget_containing(&self, text: &str) -> Option<egui::Rect> {
        self.host
            .find_widgets_where(|label| label.contains(text))
            .first()
            .copied()
    }

    /// Whether the pointer is over a plugin's UI (so clicks go to the UI, not the scene).
    pub fn pointer_over_gui(&self) -> bool {
        self.host.gui().pointer_over_gui()
    }

    /// Detaches every plugin (also done on drop).
    pub fn shutdown(&mut self) {
        self.host.shutdown();
    }
}
