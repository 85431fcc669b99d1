//! The main menu bar (File, Edit, Create, Plugins, View) and the play toolbar.

use egui_dock::DockState;
use onyx_plugin_api::tools::PluginState;
use onyx_plugin_api::{egui, Ctx, PlayMode};

use crate::create::Primitive;
use crate::file_dialog::{FileDialog, FilePurpose};
use crate::panel::{self, Panel};
use crate::state::EditorState;
use crate::unsaved_changes::{self, Discarding};

/// Draws the menu bar and the play toolbar.
pub fn menu_bar(
    ui: &mut egui::Ui,
    ctx: &mut Ctx,
    state: &mut EditorState,
    dock: &mut DockState<Panel>,
) {
    egui::MenuBar::new().ui(ui, |ui| {
        ui.menu_button("File", |ui| file_menu(ui, ctx, state));
        ui.menu_button("Edit", |ui| edit_menu(ui, ctx, state));
        ui.menu_button("Create", |ui| create_menu(ui, ctx, state));
        ui.menu_button("Plugins", |ui| plugins_menu(ui, ctx, state));
        ui.menu_button("View", |ui| view_menu(ui, dock));
        ui.separator();
        play_toolbar(ui, ctx);
        ui.separator();
        title(ui, ctx, state);
        if !state.status.is_empty() {
            ui.colored_label(egui::Color32::from_rgb(230, 160, 60), &state.status);
        }
    });
}

/// The editor's title: the scene's file name (the whole path on hover), or "untitled",
/// then " *" while it has edits that are not saved.
fn title(ui: &mut egui::Ui, ctx: &mut Ctx, state: &EditorState) {
    let path = ctx.scene_path();
    let name = scene_file_name(path.as_deref()).unwrap_or_else(|| "untitled".to_owned());
    let marker = if state.history.is_modified() {
        " *"
    } else {
        ""
    };
    let shown = ui.weak(format!("{name}{marker}"));
    if let Some(path) = path {
        shown.on_hover_text(path);
    }
}

/// The file name of the scene at `path` (`None` for an untitled scene).
pub fn scene_file_name(path: Option<&str>) -> Option<String> {
    let name = std::path::Path::new(path?).file_name()?;
    Some(name.to_string_lossy().into_owned())
}

fn file_menu(ui: &mut egui::Ui, ctx: &mut Ctx, state: &mut EditorState) {
    if ui.button("New").clicked() {
        unsaved_changes::run_or_ask(ctx, state, Discarding::New);
    }
    if ui.button("Open…").clicked() {
        state.file_dialog = Some(FileDialog::new(FilePurpose::Open, &scene_dir(ctx)));
    }
    if ui.button("Save").clicked() {
        save(ctx, state);
    }
    if ui.button("Save As…").clicked() {
        // In the scene's folder with its name filled in, else in the folder scenes live in.
        let start = ctx
            .scene_path()
            .map(std::path::PathBuf::from)
            .filter(|p| {
                p.parent()
                    .is_some_and(|d| d.as_os_str().is_empty() || d.is_dir())
            })
            .unwrap_or_else(|| scene_dir(ctx));
        state.file_dialog = Some(FileDialog::new(FilePurpose::SaveAs, &start));
    }
    ui.menu_button("Recent", |ui| {
        if state.recent.is_empty() {
            ui.weak("none yet");
        }
        for path in state.recent.clone() {
            if ui.button(&path).clicked() {
                unsaved_changes::run_or_ask(ctx, state, Discarding::Open(path));
            }
        }
    });
    ui.separator();
    if ui.button("Quit").clicked() {
        unsaved_changes::run_or_ask(ctx, state, Discarding::Quit);
    }
}

/// The folder of the current scene file, else `assets/scenes` when it exists, else `.`.
pub fn scene_dir(ctx: &mut Ctx) -> std::path::PathBuf {
    let from_scene = ctx.scene_path().and_then(|p| {
        std::path::Path::new(&p)
            .parent()
            .filter(|d| d.is_dir())
            .map(std::path::Path::to_path_buf)
    });
    from_scene.unwrap_or_else(|| {
        let assets = std::path::PathBuf::from("assets/scenes");
        if assets.is_dir() {
            assets
        } else {
            std::path::PathBuf::from(".")
        }
    })
}

/// Replaces the world with an empty one, without asking (see
/// [`unsaved_changes::run_or_ask`]).
pub fn new_scene(ctx: &mut Ctx, state: &mut EditorState) {
    match ctx.new_scene() {
        Ok(()) => {
            state.recovery.forget(ctx);
            state.selection.clear();
            state.history.clear();
            state.viewport.forget_camera();
        }
        Err(e) => state.report(ctx, "cannot start a new scene", e),
    }
}

/// Opens a scene file, without asking (see [`unsaved_changes::run_or_ask`]).
pub fn open_scene(ctx: &mut Ctx, state: &mut EditorState, path: &str) {
    match ctx.open_scene(path) {
        Ok(()) => {
            state.recovery.forget(ctx);
            state.selection.clear();
            state.history.clear();
            state.viewport.forget_camera();
            state.remember_scene(path);
            state.status.clear();
        }
        Err(e) => state.report(ctx, &format!("cannot open {path}"), e),
    }
}

/// File ▸ Save and Ctrl+S: to the scene's file (the one opened, saved, or given with
/// `--scene`), or through Save As for a scene that has none yet.
pub fn save(ctx: &mut Ctx, state: &mut EditorState) {
    match ctx.scene_path() {
        Some(path) => save_scene(ctx, state, &path),
        None => state.file_dialog = Some(FileDialog::new(FilePurpose::SaveAs, &scene_dir(ctx))),
    }
}

/// Saves the world to a scene file.
pub fn save_scene(ctx: &mut Ctx, state: &mut EditorState, path: &str) {
    match ctx.save_scene(path) {
        Ok(()) => {
            state.history.mark_saved();
            state.recovery.forget(ctx);
            state.remember_scene(path);
            state.status.clear();
        }
        Err(e) => state.report(ctx, &format!("cannot save {path}"), e),
    }
}

fn edit_menu(ui: &mut egui::Ui, ctx: &mut Ctx, state: &mut EditorState) {
    let editing = ctx.play_mode() == PlayMode::Edit;
    if ui
        .add_enabled(
            editing && state.history.can_undo(),
            egui::Button::new("Undo"),
        )
        .clicked()
    {
        state.undo(ctx);
    }
    if ui
        .add_enabled(
            editing && state.history.can_redo(),
            egui::Button::new("Redo"),
        )
        .clicked()
    {
        state.redo(ctx);
    }
    ui.separator();
    let any = !state.selection.is_empty();
    if ui
        .add_enabled(any, egui::Button::new("Duplicate"))
        .clicked()
    {
        state.duplicate_selection(ctx);
    }
    if ui.add_enabled(any, egui::Button::new("Delete")).clicked() {
        state.delete_selection(ctx);
    }
}

fn create_menu(ui: &mut egui::Ui, ctx: &mut Ctx, state: &mut EditorState) {
    for primitive in Primitive::ALL {
        if ui.button(primitive.label()).clicked() {
            let at = state.viewport.spawn_point();
            state.create(ctx, primitive.label(), primitive.components(at));
        }
    }
    ui.separator();
    if ui.button("Import OBJ…").clicked() {
        let models = std::path::PathBuf::from("assets/models");
        let start = if models.is_dir() { models } else { ".".into() };
        state.file_dialog = Some(FileDialog::new(FilePurpose::ImportObj, &start));
    }
    if ui.button("Import glTF…").clicked() {
        let models = std::path::PathBuf::from("assets/models");
        let start = if models.is_dir() { models } else { ".".into() };
        state.file_dialog = Some(FileDialog::new(FilePurpose::ImportGltf, &start));
    }
}

fn plugins_menu(ui: &mut egui::Ui, ctx: &mut Ctx, state: &mut EditorState) {
    let plugins = match ctx.plugins() {
        Ok(plugins) => plugins,
        Err(error) => {
            ui.colored_label(egui::Color32::LIGHT_RED, error.to_string());
            Vec::new()
        }
    };
    for info in plugins {
        let status = match &info.state {
            PluginState::Running => "running".to_owned(),
            PluginState::Faulted { stage, message } => format!("faulted in {stage}: {message}"),
        };
        ui.menu_button(format!("{} ({status})", info.name), |ui| {
            if ui.button("Reload").clicked() {
                ctx.reload_plugin(&info.name);
            }
            if ui.button("Unload").clicked() {
                ctx.unload_plugin(&info.name);
            }
        });
    }
    ui.separator();
    if ui.button("Reload all").clicked() {
        ctx.reload_all_plugins();
    }
    if ui.button("Load…").clicked() {
        // Plugin libraries usually sit beside the host's executable.
        let start = std::env::current_exe()
            .ok()
            .and_then(|exe| exe.parent().map(std::path::Path::to_path_buf))
            .unwrap_or_else(|| ".".into());
        state.file_dialog = Some(FileDialog::new(FilePurpose::LoadPlugin, &start));
    }
}

fn view_menu(ui: &mut egui::Ui, dock: &mut DockState<Panel>) {
    for panel in Panel::ALL {
        let mut shown = dock.find_tab(&panel).is_some();
        if ui.checkbox(&mut shown, panel.title()).changed() {
            panel::toggle(dock, panel);
            ui.close();
        }
    }
    ui.separator();
    if ui.button("Reset layout").clicked() {
        *dock = panel::default_layout();
        ui.close();
    }
}

fn play_toolbar(ui: &mut egui::Ui, ctx: &mut Ctx) {
    let mode = ctx.play_mode();
    if ui
        .add_enabled(mode != PlayMode::Playing, egui::Button::new("Play"))
        .clicked()
    {
        ctx.play();
    }
    if ui
        .add_enabled(mode == PlayMode::Playing, egui::Button::new("Pause"))
        .clicked()
    {
        ctx.pause();
    }
    if ui
        .add_enabled(mode == PlayMode::Paused, egui::Button::new("Step"))
        .clicked()
    {
        ctx.step();
    }
    if ui
        .add_enabled(mode != PlayMode::Edit, egui::Button::new("Stop"))
        .clicked()
    {
        ctx.stop();
    }
    ui.weak(match mode {
        PlayMode::Edit => "Editing",
        PlayMode::Playing => "Playing",
        PlayMode::Paused => "Paused",
    });
}
