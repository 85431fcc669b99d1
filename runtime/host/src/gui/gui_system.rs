//! [`GuiSystem`]: the host's side of plugin GUIs — one frame of input for every plugin that
//! draws, their outputs gathered under host texture ids, and which input the UI takes away
//! from the scene.

use std::collections::HashMap;

use egui::epaint::Primitive;
use egui::{PlatformOutput, Pos2, Rect};
use onyx_plugin_api::host::{GuiInput, GuiOutput};
use onyx_plugin_api::{InputEvent, MouseButton};

use super::gui_frame::GuiFrame;
use super::gui_input_builder::GuiInputBuilder;
use super::gui_textures::GuiTextures;
use super::viewport_request::viewport_rect;
use super::widget_query;

/// One plugin's GUI: its texture owner id (new for each loaded build) and last output.
#[derive(Debug)]
struct PluginGuiState {
    owner: u64,
    /// `false` once the plugin answered that it has no GUI: it is not called again.
    active: bool,
    output: Option<GuiOutput>,
}

/// Plugin GUIs on the host: input in, meshes and textures out, input routing.
#[derive(Default)]
pub struct GuiSystem {
    input: GuiInputBuilder,
    plugins: HashMap<String, PluginGuiState>,
    textures: GuiTextures,
    frame: GuiFrame,
    platform: PlatformOutput,
    next_owner: u64,
    accesskit: bool,
    /// Mouse buttons whose press went to the UI (their release does too).
    captured_buttons: Vec<MouseButton>,
    /// How many known plugins said they have no GUI.
    inactive: usize,
}

impl std::fmt::Debug for GuiSystem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GuiSystem")
            .field("plugins", &self.plugins)
            .field("frame", &self.frame)
            .field("accesskit", &self.accesskit)
            .finish_non_exhaustive()
    }
}

impl GuiSystem {
    /// The input builder (window size, scale factor, the window's own egui input).
    pub fn input_mut(&mut self) -> &mut GuiInputBuilder {
        &mut self.input
    }

    /// The input builder.
    pub fn input(&self) -> &GuiInputBuilder {
        &self.input
    }

    /// Whether plugins build their AccessKit tree (needed by [`GuiSystem::find_widget`]).
    pub fn set_accesskit(&mut self, enabled: bool) {
        self.accesskit = enabled;
    }

    /// Forgets a plugin's GUI (unloaded, or replaced by a new build: that one starts with a
    /// fresh egui context, so its textures are new too).
    pub fn forget(&mut self, plugin: &str) {
        if let Some(state) = self.plugins.remove(plugin) {
            self.textures.forget_owner(state.owner);
            if !state.active {
                self.inactive -= 1;
            }
        }
    }

    fn state(&mut self, plugin: &str) -> &mut PluginGuiState {
        if !self.plugins.contains_key(plugin) {
            self.next_owner += 1;
            self.plugins.insert(
                plugin.to_owned(),
                PluginGuiState {
                    owner: self.next_owner,
                    active: true,
                    output: None,
                },
            );
        }
        self.plugins
            .get_mut(plugin)
            .unwrap_or_else(|| unreachable!("inserted above"))
    }

    /// Whether none of `plugins` plugins draws a GUI (each said so): the GUI stage is skipped
    /// without looking at any of them.
    pub fn all_inactive(&self, plugins: usize) -> bool {
        self.inactive >= plugins
    }

    /// Whether `plugin` should be asked for a GUI frame (`false` once it said it has none).
    pub fn wants_call(&mut self, plugin: &str) -> bool {
        self.state(plugin).active
    }

    /// A frame in which no plugin draws: nothing is painted.
    pub fn skip_frame(&mut self) {
        self.input.discard();
        self.frame.primitives.clear();
        self.frame.viewport = None;
    }

    /// Starts a GUI frame at `time` seconds lasting `dt`: the input every plugin gets.
    pub fn begin_frame(&mut self, time: f64, dt: f32) -> GuiInput {
        self.frame.primitives.clear();
        self.frame.viewport = None;
        self.frame.pixels_per_point = self.input.pixels_per_point();
        self.platform = PlatformOutput::default();
        GuiInput {
            raw: self.input.take(time, dt),
            accesskit: self.accesskit,
        }
    }

    /// Takes `plugin`'s answer: `Some(Some(_))` a frame, `Some(None)` "no GUI" (never call
    /// again), `None` the call failed (the plugin faulted: its UI disappears).
    pub fn accept(&mut self, plugin: &str, answer: Option<Option<GuiOutput>>) {
        let state = self.state(plugin);
        let owner = state.owner;
        match answer {
            Some(Some(mut output)) => {
                let primitives = std::mem::take(&mut output.primitives);
                if output.platform.cursor_icon != egui::CursorIcon::Default {
                    self.platform.cursor_icon = output.platform.cursor_icon;
                }
                self.platform.commands.append(&mut output.platform.commands);
                if output.platform.ime.is_some() {
                    self.platform.ime = output.platform.ime.take();
                }
                self.textures.apply_sets(owner, &output.textures);
                for mut primitive in primitives {
                    if let Primitive::Mesh(mesh) = &mut primitive.primitive {
                        let Some(id) = self.textures.existing_host_id(owner, mesh.texture_id)
                        else {
                            continue;
                        };
                        mesh.texture_id = id;
                    }
                    self.frame.primitives.push(primitive);
                }
                let frees = std::mem::take(&mut output.textures.free);
                self.textures.free(owner, frees);
                // Applied above (egui insists deltas are not dropped unapplied).
                output.textures.clear();
                self.frame.pixels_per_point = output.pixels_per_point;
                let state = self.state(plugin);
                state.output = Some(output);
            }
            Some(None) => {
                let was_active = std::mem::replace(&mut state.active, false);
                state.output = None;
                if was_active {
                    self.inactive += 1;
                }
            }
            None => state.output = None,
        }
    }

    /// Ends the GUI frame (after every plugin's `draw_gui`).
    pub fn end_frame(&mut self) {
        self.frame.viewport = viewport_rect(&self.frame.primitives);
    }

    /// What to paint.
    pub fn frame(&self) -> &GuiFrame {
        &self.frame
    }

    /// The host-side egui textures.
    pub fn textures(&self) -> &GuiTextures {
        &self.textures
    }

    /// This frame's platform output of all plugins together (cursor icon of the UI under
    /// the pointer, copied text, IME), for the window to apply.
    pub fn take_platform_output(&mut self) -> PlatformOutput {
        std::mem::take(&mut self.platform)
    }

    fn outputs(&self) -> impl Iterator<Item = &GuiOutput> {
        self.plugins.values().filter_map(|s| s.output.as_ref())
    }

    /// Whether the pointer at `pos` (points) is over some plugin's UI and not over the
    /// scene viewport shown inside it.
    pub fn covers(&self, pos: Pos2) -> bool {
        let in_viewport = self.frame.viewport.is_some_and(|r| r.contains(pos));
        self.outputs().any(|output| {
            output.floating_areas.iter().any(|r| r.contains(pos))
                || (!output.free_rect.contains(pos) && !in_viewport)
        })
    }

    /// Whether the pointer is over a UI (as of the last frame).
    pub fn pointer_over_gui(&self) -> bool {
        self.input.pointer().is_some_and(|pos| self.covers(pos))
    }

    fn using_pointer(&self) -> bool {
        self.outputs().any(|o| o.using_pointer)
    }

    fn wants_keyboard(&self) -> bool {
        self.outputs().any(|o| o.wants_keyboard)
    }

    /// Feeds `event` to the GUI input and says whether the scene gets it too (`false`: a UI
    /// took it — a click on a window, scrolling over a panel, typing into a text field).
    /// Decided with the UI as of the last frame, as egui integrations do.
    pub fn route(&mut self, event: &InputEvent) -> bool {
        self.input.push(event);
        match event {
            InputEvent::CursorMoved { .. } => true,
            InputEvent::MouseButton { button, pressed } => {
                if *pressed {
                    if self.using_pointer() || self.pointer_over_gui() {
                        self.captured_buttons.push(*button);
                        return false;
                    }
                    true
                } else if let Some(i) = self.captured_buttons.iter().position(|b| b == button) {
                    self.captured_buttons.swap_remove(i);
                    false
                } else {
                    true
                }
            }
            InputEvent::Scroll { .. } => !self.pointer_over_gui(),
            InputEvent::MouseMotion { .. } => {
                self.captured_buttons.is_empty() && !self.using_pointer()
            }
            InputEvent::Key { pressed, .. } => !*pressed || !self.wants_keyboard(),
            InputEvent::Text(_) => !self.wants_keyboard(),
        }
    }

    /// The screen rectangles (points) of the widgets labelled `label` in the topmost plugin
    /// UI that has any, in tree order. Needs [`GuiSystem::set_accesskit`] on and a frame
    /// drawn since.
    pub fn find_widgets(&self, plugin_order: &[&str], label: &str) -> Vec<Rect> {
        self.find_widgets_where(plugin_order, |text| text == label)
    }

    /// [`GuiSystem::find_widgets`] for the widgets whose label (or value) passes `test`.
    pub fn find_widgets_where(
        &self,
        plugin_order: &[&str],
        test: impl Fn(&str) -> bool,
    ) -> Vec<Rect> {
        plugin_order
            .iter()
            .rev()
            .filter_map(|name| {
                let output = self.plugins.get(*name)?.output.as_ref()?;
                let tree = output.platform.accesskit_update.as_ref()?;
                let found = widget_query::find_widgets_where(tree, &test);
                (!found.is_empty()).then_some(found)
            })
            .next()
            .unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn window_at(rect: Rect) -> GuiOutput {
        GuiOutput {
            primitives: Vec::new(),
            textures: Default::default(),
            platform: PlatformOutput::default(),
            pixels_per_point: 1.0,
            using_pointer: false,
            wants_keyboard: false,
            floating_areas: vec![rect],
            free_rect: Rect::EVERYTHING,
        }
    }

    fn click(gui: &mut GuiSystem, x: f32, y: f32) -> [bool; 2] {
        gui.route(&InputEvent::CursorMoved { x, y });
        [true, false].map(|pressed| {
            gui.route(&InputEvent::MouseButton {
                button: MouseButton::Left,
                pressed,
            })
        })
    }

    #[test]
    fn a_click_on_a_window_is_the_uis_and_beside_it_the_scenes() {
        let mut gui = GuiSystem::default();
        let window = Rect::from_min_max(Pos2::new(10.0, 10.0), Pos2::new(110.0, 60.0));
        gui.begin_frame(0.0, 0.016);
        gui.accept("p", Some(Some(window_at(window))));
        gui.end_frame();
        assert_eq!(click(&mut gui, 50.0, 30.0), [false, false]);
        assert_eq!(click(&mut gui, 500.0, 300.0), [true, true]);
        // A press beside the window keeps its release even if the pointer moved onto it.
        gui.route(&InputEvent::MouseButton {
            button: MouseButton::Left,
            pressed: true,
        });
        gui.route(&InputEvent::CursorMoved { x: 50.0, y: 30.0 });
        assert!(gui.route(&InputEvent::MouseButton {
            button: MouseButton::Left,
            pressed: false,
        }));
    }

    #[test]
    fn a_plugin_without_gui_is_asked_once() {
        let mut gui = GuiSystem::default();
        assert!(gui.wants_call("idle"));
        assert!(!gui.all_inactive(1));
        gui.begin_frame(0.0, 0.016);
        gui.accept("idle", Some(None));
        assert!(!gui.wants_call("idle"));
        assert!(gui.all_inactive(1));
        gui.forget("idle");
        assert!(gui.wants_call("idle"), "a new build may draw");
    }
}
