//! [`EditorState`]: what the panels share — selection, history, per-panel state.

use std::path::PathBuf;

use onyx_plugin_api::tools::EntityList;
use onyx_plugin_api::{Ctx, Entity, Name};

use crate::console::ConsoleState;
use crate::diagnostics_panel::DiagnosticsState;
use crate::file_dialog::FileDialog;
use crate::hierarchy::HierarchyState;
use crate::history::{snapshot, Command, History};
use crate::inspector::InspectorState;
use crate::viewport::ViewportState;

/// Most recent scenes kept in File ▸ Recent.
const RECENT_LIMIT: usize = 8;

/// Everything the editor knows besides its dock layout.
#[derive(Default)]
pub struct EditorState {
    /// Where the dock layout is saved.
    pub layout_path: PathBuf,
    /// Selected entities; the last is the primary one (the inspector's).
    pub selection: Vec<Entity>,
    /// Undo/redo.
    pub history: History,
    /// Every entity with its name, read once per frame.
    pub entities: EntityList,
    /// Frames drawn.
    pub frame: u64,
    /// The hierarchy panel.
    pub hierarchy: HierarchyState,
    /// The inspector panel.
    pub inspector: InspectorState,
    /// The viewport panel and the fly camera.
    pub viewport: ViewportState,
    /// The console panel.
    pub console: ConsoleState,
    /// The diagnostics panel.
    pub diagnostics: DiagnosticsState,
    /// The open file dialog.
    pub file_dialog: Option<FileDialog>,
    /// Recently opened or saved scenes, newest first.
    pub recent: Vec<String>,
    /// The last error, shown in the status line.
    pub status: String,
}

impl EditorState {
    /// The primary selection.
    pub fn primary(&self) -> Option<Entity> {
        self.selection.last().copied()
    }

    /// Selects only `entity`.
    pub fn select(&mut self, entity: Entity) {
        self.selection.clear();
        self.selection.push(entity);
    }

    /// Adds `entity` to the selection or takes it out.
    pub fn toggle_selected(&mut self, entity: Entity) {
        match self.selection.iter().position(|e| *e == entity) {
            Some(i) => {
                self.selection.remove(i);
            }
            None => self.selection.push(entity),
        }
    }

    /// Puts `path` first in the recent list.
    pub fn remember_scene(&mut self, path: &str) {
        self.recent.retain(|p| p != path);
        self.recent.insert(0, path.to_owned());
        self.recent.truncate(RECENT_LIMIT);
    }

    /// Shows an error in the status line and the log.
    pub fn report(&mut self, ctx: &mut Ctx, what: &str, error: impl std::fmt::Display) {
        self.status = format!("{what}: {error}");
        ctx.warn(&self.status);
    }

    /// Runs an edit already applied into history when in Edit mode.
    pub fn record(&mut self, ctx: &Ctx, command: Command) {
        if ctx.play_mode() == onyx_plugin_api::PlayMode::Edit {
            self.history.record(command);
        }
    }

    /// Records a component change, merging a drag into one edit (Edit mode only).
    pub fn record_merged(&mut self, ctx: &Ctx, command: Command) {
        if ctx.play_mode() == onyx_plugin_api::PlayMode::Edit {
            self.history.record_merged(command, self.frame);
        }
    }

    /// Spawns an entity from components and records it.
    pub fn create(&mut self, ctx: &mut Ctx, name: &str, components: Vec<(String, String)>) {
        let mut all = vec![("Name".to_owned(), json_string(name))];
        all.extend(components);
        match crate::history::respawn(ctx, &all) {
            Ok(entity) => {
                self.record(
                    ctx,
                    Command::Create {
                        entity,
                        components: all,
                    },
                );
                self.select(entity);
            }
            Err(e) => self.report(ctx, &format!("cannot create {name}"), e),
        }
    }

    /// Deletes the selection (undoable).
    pub fn delete_selection(&mut self, ctx: &mut Ctx) {
        for entity in std::mem::take(&mut self.selection) {
            let components = match snapshot(ctx, entity) {
                Ok(c) => c,
                Err(e) => {
                    self.report(ctx, "cannot delete", e);
                    continue;
                }
            };
            match ctx.despawn(entity) {
                Ok(()) => self.record(ctx, Command::Delete { entity, components }),
                Err(e) => self.report(ctx, "cannot delete", e),
            }
        }
    }

    /// Duplicates the selection (undoable); the copies become the selection.
    pub fn duplicate_selection(&mut self, ctx: &mut Ctx) {
        let mut copies = Vec::new();
        for entity in std::mem::take(&mut self.selection) {
            let result = snapshot(ctx, entity).and_then(|mut components| {
                for (type_name, json) in &mut components {
                    if type_name == "Name" {
                        let name: Name = serde_json::from_str(json).unwrap_or_default();
                        *json = json_string(&format!("{} copy", name.as_str()));
                    }
                }
                let copy = crate::history::respawn(ctx, &components)?;
                Ok((copy, components))
            });
            match result {
                Ok((copy, components)) => {
                    self.record(
                        ctx,
                        Command::Create {
                            entity: copy,
                            components,
                        },
                    );
                    copies.push(copy);
                }
                Err(e) => self.report(ctx, "cannot duplicate", e),
            }
        }
        self.selection = copies;
    }

    /// Undoes the last edit.
    pub fn undo(&mut self, ctx: &mut Ctx) {
        if let Err(e) = self.history.undo(ctx) {
            self.report(ctx, "cannot undo", e);
        }
        self.selection.retain(|e| ctx.contains(*e));
    }

    /// Redoes the last undone edit.
    pub fn redo(&mut self, ctx: &mut Ctx) {
        if let Err(e) = self.history.redo(ctx) {
            self.report(ctx, "cannot redo", e);
        }
        self.selection.retain(|e| ctx.contains(*e));
    }

    /// The label of row `index` of the entity list: its name, or `Entity N`.
    pub fn row_label(&self, index: usize) -> std::borrow::Cow<'_, str> {
        let name = self.entities.name(index);
        if name.is_empty() {
            let id = self.entities.entities().get(index).copied();
            std::borrow::Cow::Owned(format!(
                "Entity {}",
                id.map(|e| e.to_bits() & 0xffff_ffff).unwrap_or(0)
            ))
        } else {
            std::borrow::Cow::Borrowed(name)
        }
    }
}

/// `text` as a JSON string.
pub fn json_string(text: &str) -> String {
    serde_json::Value::String(text.to_owned()).to_string()
}
