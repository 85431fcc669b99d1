//! The Onyx editor, a plugin like any other: dockable Hierarchy, Inspector, Viewport,
//! Console and Diagnostics panels, a main menu, undo/redo, a fly camera and a translate
//! gizmo, and the play toolbar.
//!
//! Nothing is lost: Quit, the window's close button, New and Open ask "Save changes?" while
//! the scene has unsaved edits ([`unsaved_changes`]), and those edits are autosaved to a
//! recovery copy offered back at the next start after a crash ([`recovery`]).
//!
//! Settings: `editor.layout=FILE` (default `.onyx/editor-layout.json`): where the dock
//! layout is restored from at attach and saved to at detach; `editor.autosave=SECS`
//! (default 30, 0: off) and `editor.recovery=DIR` (default `.onyx/recovery`): see
//! [`recovery`].

#![warn(missing_docs)]

pub mod atomic_file;
pub mod console;
pub mod create;
pub mod diagnostics_panel;
pub mod file_dialog;
pub mod hierarchy;
pub mod history;
pub mod inspector;
pub mod json_tree;
pub mod menu;
pub mod panel;
pub mod recovery;
pub mod state;
pub mod unsaved_changes;
pub mod viewport;

use std::path::PathBuf;

use egui_dock::{DockArea, DockState, TabViewer};
use onyx_plugin_api::{
    egui, export_plugin, AttachInfo, Ctx, Event, Flow, PlayMode, Plugin, PluginError, WindowEvent,
};
use serde::{Deserialize, Serialize};

use crate::file_dialog::{DialogResult, FilePurpose};
use crate::panel::Panel;
use crate::recovery::Recovery;
use crate::state::EditorState;
use crate::unsaved_changes::Discarding;

/// The editor plugin.
pub struct Editor {
    dock: DockState<Panel>,
    state: EditorState,
}

impl Default for Editor {
    fn default() -> Self {
        Self {
            dock: panel::default_layout(),
            state: EditorState::default(),
        }
    }
}

/// What survives a hot reload of the editor.
#[derive(Default, Serialize, Deserialize)]
#[serde(default)]
struct Kept {
    dock: Option<DockState<Panel>>,
    selection: Vec<u64>,
    recent: Vec<String>,
    camera: viewport::FlyCamera,
    /// The scene has unsaved edits (the undo history itself does not survive).
    modified: bool,
    /// Recovery copies still waiting for an answer.
    recovery_offers: Vec<recovery::Offer>,
}

impl Plugin for Editor {
    fn on_attach(&mut self, ctx: &mut Ctx, info: &AttachInfo) -> Result<(), PluginError> {
        self.state.layout_path = info
            .setting("layout")
            .map(PathBuf::from)
            .unwrap_or_else(|| PathBuf::from(panel::DEFAULT_LAYOUT_PATH));
        // A reload brought the offer still waiting (load_state runs first): keep it.
        let offers = std::mem::take(&mut self.state.recovery.offers);
        self.state.recovery = Recovery::from_settings(ctx, info);
        self.state.recovery.offers = offers;
        if !info.reload {
            self.state.recovery.look_for_copies();
            match panel::load_layout(&self.state.layout_path) {
                Ok(Some(dock)) => self.dock = dock,
                Ok(None) => {}
                Err(e) => ctx.warn(format!(
                    "editor layout {} ignored, using the default layout: {e}",
                    self.state.layout_path.display()
                )),
            }
            ctx.stop();
        }
        Ok(())
    }

    fn on_event(&mut self, ctx: &mut Ctx, event: &Event) {
        if matches!(event, Event::Window(WindowEvent::CloseRequested))
            && self.state.history.is_modified()
        {
            ctx.prevent_close();
            self.state.asking = Some(Discarding::Quit);
        }
    }

    fn on_update(&mut self, ctx: &mut Ctx, _dt: f32) -> Flow {
        self.state.console.poll(ctx);
        self.state.diagnostics.poll(ctx);
        self.state.recovery.tick(ctx, &self.state.history);
        Flow::Continue
    }

    fn draw_gui(&mut self, ctx: &mut Ctx, ui: &mut egui::Ui) {
        let state = &mut self.state;
        state.frame += 1;
        state.entities = ctx.entity_list();
        state.selection.retain(|e| ctx.contains(*e));
        state.viewport.ensure_camera(ctx);

        shortcuts(ui, ctx, state);
        egui::Panel::top("editor-menu").show(ui, |ui| {
            menu::menu_bar(ui, ctx, state, &mut self.dock);
        });
        egui::CentralPanel::default()
            .frame(egui::Frame::NONE)
            .show(ui, |ui| {
                let mut tabs = Tabs { ctx, state };
                DockArea::new(&mut self.dock)
                    .show_add_buttons(false)
                    .show_leaf_collapse_buttons(false)
                    .show_inside(ui, &mut tabs);
            });
        if let Some(dialog) = &mut state.file_dialog {
            match dialog.show(ui.ctx()) {
                DialogResult::Open => {}
                DialogResult::Cancelled => {
                    state.file_dialog = None;
                    state.after_save = None;
                }
                DialogResult::Chosen(path) => {
                    let purpose = dialog.purpose;
                    state.file_dialog = None;
                    match purpose {
                        FilePurpose::Open => {
                            unsaved_changes::run_or_ask(ctx, state, Discarding::Open(path));
                        }
                        FilePurpose::SaveAs => {
                            menu::save_scene(ctx, state, &path);
                            // Saved for "Save changes?": the action it was asked for follows.
                            if let Some(action) = state.after_save.take() {
                                if !state.history.is_modified() {
                                    unsaved_changes::run(ctx, state, action);
                                }
                            }
                        }
                        FilePurpose::ImportObj => create::import_obj(ctx, state, &path),
                        FilePurpose::LoadPlugin => ctx.load_plugin(&path),
                    }
                }
            }
        }
        unsaved_changes::show(ui, ctx, state);
        recovery::show_offer(ui, ctx, state);
    }

    fn on_detach(&mut self, ctx: &mut Ctx) {
        let state = &mut self.state;
        state
            .recovery
            .on_detach(ctx, &state.history, state.quitting);
        if let Err(e) = panel::save_layout(&self.state.layout_path, &self.dock) {
            ctx.warn(format!(
                "cannot save the editor layout to {}: {e}",
                self.state.layout_path.display()
            ));
        }
    }

    fn save_state(&self) -> Result<Vec<u8>, PluginError> {
        onyx_plugin_api::state::encode(&Kept {
            dock: Some(self.dock.clone()),
            selection: self.state.selection.iter().map(|e| e.to_bits()).collect(),
            recent: self.state.recent.clone(),
            camera: self.state.viewport.camera.clone(),
            modified: self.state.history.is_modified(),
            recovery_offers: self.state.recovery.offers.clone(),
        })
    }

    fn load_state(&mut self, bytes: &[u8]) -> Result<(), PluginError> {
        let kept: Kept = onyx_plugin_api::state::decode(bytes)?;
        if let Some(dock) = kept.dock {
            self.dock = dock;
        }
        self.state.selection = kept
            .selection
            .into_iter()
            .map(onyx_plugin_api::Entity::from_bits)
            .collect();
        self.state.recent = kept.recent;
        self.state.viewport.camera = kept.camera;
        if kept.modified {
            self.state.history.mark_modified();
        }
        self.state.recovery.offers = kept.recovery_offers;
        Ok(())
    }
}

/// Ctrl+Z / Ctrl+Y / Ctrl+Shift+Z, Ctrl+D, Delete, Ctrl+S — unless a text field has the keys.
fn shortcuts(ui: &mut egui::Ui, ctx: &mut Ctx, state: &mut EditorState) {
    if ui.ctx().egui_wants_keyboard_input() {
        return;
    }
    let (undo, redo, duplicate, delete, save) = ui.input(|i| {
        let command = i.modifiers.command;
        (
            command && !i.modifiers.shift && i.key_pressed(egui::Key::Z),
            command
                && (i.key_pressed(egui::Key::Y)
                    || (i.modifiers.shift && i.key_pressed(egui::Key::Z))),
            command && i.key_pressed(egui::Key::D),
            i.key_pressed(egui::Key::Delete),
            command && i.key_pressed(egui::Key::S),
        )
    });
    let editing = ctx.play_mode() == PlayMode::Edit;
    if undo && editing {
        state.undo(ctx);
    }
    if redo && editing {
        state.redo(ctx);
    }
    if duplicate {
        state.duplicate_selection(ctx);
    }
    if delete {
        state.delete_selection(ctx);
    }
    if save {
        menu::save(ctx, state);
    }
}

/// Draws each panel with the host context and the editor's state.
struct Tabs<'a, 'h> {
    ctx: &'a mut Ctx<'h>,
    state: &'a mut EditorState,
}

impl TabViewer for Tabs<'_, '_> {
    type Tab = Panel;

    fn title(&mut self, tab: &mut Panel) -> egui::WidgetText {
        tab.title().into()
    }

    fn id(&mut self, tab: &mut Panel) -> egui::Id {
        egui::Id::new(tab.title())
    }

    /// egui_dock paints tab titles itself: name each tab for AccessKit (screen readers, and
    /// tests that find widgets by label).
    fn on_tab_button(&mut self, tab: &mut Panel, response: &egui::Response) {
        let title = tab.title();
        response.widget_info(|| egui::WidgetInfo::labeled(egui::WidgetType::Button, true, title));
    }

    fn ui(&mut self, ui: &mut egui::Ui, tab: &mut Panel) {
        match tab {
            Panel::Hierarchy => hierarchy::show(ui, self.ctx, self.state),
            Panel::Inspector => inspector::show(ui, self.ctx, self.state),
            Panel::Viewport => viewport::show(ui, self.ctx, self.state),
            Panel::Console => self.state.console.show(ui),
            Panel::Diagnostics => self.state.diagnostics.show(ui),
        }
    }
}

export_plugin!(Editor);
