//! The Hierarchy panel: every entity, a filter, selection, rename in place.

use onyx_plugin_api::{egui, Ctx, Entity};

use crate::history::Command;
use crate::state::{json_string, EditorState};

/// The hierarchy's own state.
#[derive(Debug, Default)]
pub struct HierarchyState {
    /// Text a row must contain (case-insensitive) to be shown.
    pub filter: String,
    /// The entity being renamed and the name typed so far.
    pub renaming: Option<(Entity, String)>,
    rows: Vec<usize>,
}

/// Draws the panel. Only the rows in view are laid out, so 10,000 entities cost little.
pub fn show(ui: &mut egui::Ui, ctx: &mut Ctx, state: &mut EditorState) {
    ui.horizontal(|ui| {
        ui.label("Filter");
        ui.add(
            egui::TextEdit::singleline(&mut state.hierarchy.filter)
                .hint_text("name")
                .desired_width(f32::INFINITY),
        );
    });
    ui.weak(format!("{} entities", state.entities.len()));
    ui.separator();

    let filter = state.hierarchy.filter.to_lowercase();
    let mut rows = std::mem::take(&mut state.hierarchy.rows);
    rows.clear();
    if filter.is_empty() {
        rows.extend(0..state.entities.len());
    } else {
        rows.extend((0..state.entities.len()).filter(|&i| {
            let label = state.row_label(i);
            if label.is_ascii() && filter.is_ascii() {
                label
                    .as_bytes()
                    .windows(filter.len())
                    .any(|w| w.eq_ignore_ascii_case(filter.as_bytes()))
            } else {
                label.to_lowercase().contains(&filter)
            }
        }));
    }

    let row_height = ui.spacing().interact_size.y;
    let mut clicked: Option<(Entity, bool)> = None;
    let mut start_rename: Option<Entity> = None;
    let mut commit: Option<(Entity, String)> = None;
    egui::ScrollArea::vertical()
        .auto_shrink([false, false])
        .show_rows(ui, row_height, rows.len(), |ui, range| {
            for &index in &rows[range] {
                let Some(&entity) = state.entities.entities().get(index) else {
                    continue;
                };
                if let Some((renamed, text)) = &mut state.hierarchy.renaming {
                    if *renamed == entity {
                        let response =
                            ui.add(egui::TextEdit::singleline(text).desired_width(f32::INFINITY));
                        if !response.has_focus() && !response.lost_focus() {
                            response.request_focus();
                        }
                        if response.lost_focus() {
                            commit = Some((entity, text.clone()));
                        }
                        continue;
                    }
                }
                let selected = state.selection.contains(&entity);
                let response = ui.add_sized(
                    [ui.available_width(), row_height],
                    egui::Button::selectable(selected, state.row_label(index).as_ref()),
                );
                if response.double_clicked() {
                    start_rename = Some(entity);
                } else if response.clicked() {
                    let multi = ui.input(|i| i.modifiers.command || i.modifiers.shift);
                    clicked = Some((entity, multi));
                }
            }
        });
    state.hierarchy.rows = rows;

    if let Some((entity, multi)) = clicked {
        if multi {
            state.toggle_selected(entity);
        } else {
            state.select(entity);
        }
    }
    if let Some(entity) = start_rename {
        let index = state.entities.entities().iter().position(|e| *e == entity);
        let name = index
            .map(|i| state.entities.name(i).to_owned())
            .unwrap_or_default();
        state.hierarchy.renaming = Some((entity, name));
        state.select(entity);
    }
    if let Some((entity, name)) = commit {
        state.hierarchy.renaming = None;
        rename(ctx, state, entity, &name);
    }
}

/// Renames `entity` (undoable).
pub fn rename(ctx: &mut Ctx, state: &mut EditorState, entity: Entity, name: &str) {
    let old = ctx
        .components_of(entity)
        .ok()
        .and_then(|c| c.into_iter().find(|c| c.type_name == "Name"))
        .map(|c| c.value);
    let new = json_string(name);
    if old.as_deref() == Some(new.as_str()) {
        return;
    }
    match ctx.set_component_json(entity, "Name", &new) {
        Ok(()) => state.record(
            ctx,
            Command::SetComponent {
                entity,
                type_name: "Name".to_owned(),
                old,
                new: Some(new),
            },
        ),
        Err(e) => state.report(ctx, "cannot rename", e),
    }
}
