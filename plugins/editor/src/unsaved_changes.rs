//! "Save changes?": every action that would throw the open scene away (Quit, closing the
//! window, New, Open, a recent scene) asks first while the scene has unsaved edits.
//!
//! The answer is one of three: **Save** (to the scene's file, or through Save As for an
//! untitled scene, then the action), **Don't Save** (the action, and the recovery copy is
//! deleted: the user chose to lose those edits) or **Cancel** (nothing happens).

use onyx_plugin_api::{egui, Ctx};

use crate::file_dialog::{FileDialog, FilePurpose};
use crate::menu;
use crate::state::EditorState;

/// An action that replaces or ends the open scene.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Discarding {
    /// File ▸ Quit, or the window's close button.
    Quit,
    /// File ▸ New.
    New,
    /// File ▸ Open… (the file already chosen) or File ▸ Recent.
    Open(String),
}

impl Discarding {
    /// What the question says the action will do.
    fn verb(&self) -> &'static str {
        match self {
            Discarding::Quit => "quitting",
            Discarding::New => "starting a new scene",
            Discarding::Open(_) => "opening another scene",
        }
    }
}

/// Runs `action` now when the scene has no unsaved edits, else asks first (the question
/// shows from the next frame on).
pub fn run_or_ask(ctx: &mut Ctx, state: &mut EditorState, action: Discarding) {
    if state.history.is_modified() {
        state.asking = Some(action);
    } else {
        run(ctx, state, action);
    }
}

/// Runs `action` without asking.
pub fn run(ctx: &mut Ctx, state: &mut EditorState, action: Discarding) {
    match action {
        Discarding::Quit => {
            state.quitting = true;
            ctx.request_quit();
        }
        Discarding::New => menu::new_scene(ctx, state),
        Discarding::Open(path) => menu::open_scene(ctx, state, &path),
    }
}

/// What the user answered.
enum Answer {
    Save,
    DontSave,
    Cancel,
}

/// Shows the question while an action waits for an answer, and acts on the answer.
pub fn show(ui: &egui::Ui, ctx: &mut Ctx, state: &mut EditorState) {
    let Some(action) = state.asking.clone() else {
        return;
    };
    let name = menu::scene_file_name(ctx.scene_path().as_deref())
        .unwrap_or_else(|| "The untitled scene".to_owned());
    let mut answer = None;
    let modal = egui::Modal::new(egui::Id::new("editor-unsaved-changes")).show(ui.ctx(), |ui| {
        ui.heading("Save changes?");
        ui.label(format!(
            "{name} has changes that are not saved. Save them before {}?",
            action.verb()
        ));
        ui.add_space(8.0);
        ui.horizontal(|ui| {
            if ui.button("Save").clicked() {
                answer = Some(Answer::Save);
            }
            if ui.button("Don't Save").clicked() {
                answer = Some(Answer::DontSave);
            }
            if ui.button("Cancel").clicked() {
                answer = Some(Answer::Cancel);
            }
        });
    });
    if modal.should_close() && answer.is_none() {
        answer = Some(Answer::Cancel); // Escape or a click beside the question
    }
    let Some(answer) = answer else {
        return;
    };
    state.asking = None;
    match answer {
        Answer::Cancel => {}
        Answer::DontSave => {
            state.recovery.forget(ctx);
            run(ctx, state, action);
        }
        Answer::Save => match ctx.scene_path() {
            Some(path) => {
                menu::save_scene(ctx, state, &path);
                if !state.history.is_modified() {
                    run(ctx, state, action);
                }
            }
            None => {
                // An untitled scene: Save As first; the action follows a successful save.
                state.after_save = Some(action);
                state.file_dialog =
                    Some(FileDialog::new(FilePurpose::SaveAs, &menu::scene_dir(ctx)));
            }
        },
    }
}
