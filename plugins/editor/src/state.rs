//! [`EditorState`]: what the panels share — selection, history, per-panel state.

use std::path::PathBuf;

use onyx_plugin_api::tools::{ComponentValue, EntityList};
use onyx_plugin_api::{BuiltinValue, Ctx, CtxError, Entity, Name, Parent};

use crate::console::ConsoleState;
use crate::diagnostics_panel::DiagnosticsState;
use crate::file_dialog::FileDialog;
use crate::hierarchy::HierarchyState;
use crate::history::{snapshot, Command, History};
use crate::inspector::InspectorState;
use crate::recovery::Recovery;
use crate::unsaved_changes::Discarding;
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
    /// An action waiting for the answer to "Save changes?".
    pub asking: Option<Discarding>,
    /// An action to run once Save As has saved the untitled scene.
    pub after_save: Option<Discarding>,
    /// The editor asked the host to quit after the scene was saved or its edits thrown
    /// away on purpose (no recovery copy is kept).
    pub quitting: bool,
    /// Autosave and the recovery copy.
    pub recovery: Recovery,
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
    pub fn create(&mut self, ctx: &mut Ctx, name: &str, components: Vec<ComponentValue>) {
        let mut all = vec![ComponentValue::Builtin(Name::new(name).into())];
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

    /// The selected entities that have no selected ancestor: acting on each one's subtree
    /// acts on every selected entity once.
    pub fn selected_roots(&self) -> Vec<Entity> {
        self.selection
            .iter()
            .copied()
            .filter(|e| !self.ancestors(*e).any(|a| self.selection.contains(&a)))
            .collect()
    }

    /// The ancestors of `entity` in this frame's entity list, nearest first.
    pub fn ancestors(&self, entity: Entity) -> impl Iterator<Item = Entity> + '_ {
        let list = &self.entities;
        let mut row = list.entities().iter().position(|e| *e == entity);
        std::iter::from_fn(move || {
            let parent = list.parent(row?)?;
            row = Some(parent);
            list.entities().get(parent).copied()
        })
        .take(list.len())
    }

    /// Deletes the selection with everything below it (one undoable step).
    pub fn delete_selection(&mut self, ctx: &mut Ctx) {
        let mut done = Vec::new();
        for root in self.selected_roots() {
            match delete_subtree(ctx, root) {
                Ok(commands) => done.extend(commands),
                Err(e) => self.report(ctx, "cannot delete", e),
            }
        }
        self.selection.clear();
        if let Some(command) = Command::group(done) {
            self.record(ctx, command);
        }
    }

    /// Duplicates the selection with everything below it (one undoable step); the copies
    /// of the selected entities become the selection.
    pub fn duplicate_selection(&mut self, ctx: &mut Ctx) {
        let mut copies = Vec::new();
        let mut done = Vec::new();
        for root in self.selected_roots() {
            match duplicate_subtree(ctx, root) {
                Ok((copy, commands)) => {
                    copies.push(copy);
                    done.extend(commands);
                }
                Err(e) => self.report(ctx, "cannot duplicate", e),
            }
        }
        self.selection = copies;
        if let Some(command) = Command::group(done) {
            self.record(ctx, command);
        }
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

/// `entity` and every entity below it, parents before children.
pub fn subtree(ctx: &mut Ctx, entity: Entity) -> Result<Vec<Entity>, CtxError> {
    let mut out = vec![entity];
    let mut i = 0;
    while i < out.len() {
        let children = ctx.children(out[i])?;
        out.extend(children);
        i += 1;
    }
    Ok(out)
}

/// Deletes `root` with its subtree; the edits, children first (so undoing them, last to
/// first, brings parents back before their children).
fn delete_subtree(ctx: &mut Ctx, root: Entity) -> Result<Vec<Command>, CtxError> {
    let entities = subtree(ctx, root)?;
    let mut commands = Vec::with_capacity(entities.len());
    for &entity in entities.iter().rev() {
        let components = snapshot(ctx, entity)?;
        commands.push(Command::Delete { entity, components });
    }
    ctx.despawn_recursive(root)?;
    Ok(commands)
}

/// Copies `root` with its subtree (the copy of `root` named "… copy", under the same
/// parent; the copies of its descendants under the copies of their parents).
fn duplicate_subtree(ctx: &mut Ctx, root: Entity) -> Result<(Entity, Vec<Command>), CtxError> {
    let entities = subtree(ctx, root)?;
    let mut copy_of: Vec<(Entity, Entity)> = Vec::with_capacity(entities.len());
    let mut commands = Vec::with_capacity(entities.len());
    for &entity in &entities {
        let mut components = snapshot(ctx, entity)?;
        for value in &mut components {
            match value {
                ComponentValue::Builtin(BuiltinValue::Name(name)) if entity == root => {
                    *name = Name::new(format!("{} copy", name.as_str()));
                }
                ComponentValue::Builtin(BuiltinValue::Parent(Parent(parent))) => {
                    if let Some((_, copy)) = copy_of.iter().find(|(from, _)| from == parent) {
                        *parent = *copy;
                    }
                }
                _ => {}
            }
        }
        let copy = crate::history::respawn(ctx, &components)?;
        copy_of.push((entity, copy));
        commands.push(Command::Create {
            entity: copy,
            components,
        });
    }
    let copy = copy_of.first().map_or(root, |(_, copy)| *copy);
    Ok((copy, commands))
}
