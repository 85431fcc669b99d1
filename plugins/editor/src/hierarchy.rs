//! The Hierarchy panel: the scene graph as a tree — expand and collapse, a filter that keeps
//! the ancestors of what it finds, selection, rename in place, and drag and drop to
//! re-parent (onto a row) or un-parent (onto the root area), undoably and keeping the world
//! pose.

use std::collections::HashSet;

use onyx_plugin_api::tools::{ComponentKey, ComponentValue, EntityList};
use onyx_plugin_api::{egui, BuiltinId, Ctx, Entity, KeepPose, Name};

use crate::history::Command;
use crate::state::EditorState;

/// Indent per level of the tree, points.
const INDENT: f32 = 14.0;
/// Width of the expand/collapse toggle, points.
const TOGGLE_WIDTH: f32 = 16.0;
/// The label of the area below the rows that entities are dropped on to become roots.
pub const ROOT_DROP_LABEL: &str = "Drop here to make it a root";

/// One visible row: a row of the entity list, at a depth of the tree.
#[derive(Clone, Copy, Debug)]
struct Row {
    index: usize,
    depth: usize,
    has_children: bool,
}

/// The hierarchy's own state.
#[derive(Debug, Default)]
pub struct HierarchyState {
    /// Text a row must contain (case-insensitive) to be shown; the rows above a match are
    /// shown too.
    pub filter: String,
    /// The entity being renamed and the name typed so far.
    pub renaming: Option<(Entity, String)>,
    /// Entities whose children are hidden.
    pub collapsed: HashSet<Entity>,
    rows: Vec<Row>,
    tree: Tree,
}

/// The entity list's parent links as child lists (compressed rows: the children of row `i`
/// are `children[starts[i]..starts[i + 1]]`), rebuilt each frame without an allocation per
/// entity.
#[derive(Debug, Default)]
struct Tree {
    starts: Vec<u32>,
    children: Vec<u32>,
    roots: Vec<u32>,
}

impl Tree {
    fn build(&mut self, list: &EntityList) {
        let n = list.len();
        self.starts.clear();
        self.starts.resize(n + 1, 0);
        self.roots.clear();
        for i in 0..n {
            match list.parent(i) {
                Some(p) => self.starts[p + 1] += 1,
                None => self.roots.push(i as u32),
            }
        }
        for i in 0..n {
            self.starts[i + 1] += self.starts[i];
        }
        self.children.clear();
        self.children.resize(self.starts[n] as usize, 0);
        let mut fill: Vec<u32> = self.starts[..n].to_vec();
        for i in 0..n {
            if let Some(p) = list.parent(i) {
                self.children[fill[p] as usize] = i as u32;
                fill[p] += 1;
            }
        }
    }

    fn children(&self, row: usize) -> &[u32] {
        let (a, b) = (self.starts[row] as usize, self.starts[row + 1] as usize);
        &self.children[a..b]
    }
}

fn matches(label: &str, filter: &str) -> bool {
    if label.is_ascii() && filter.is_ascii() {
        label
            .as_bytes()
            .windows(filter.len())
            .any(|w| w.eq_ignore_ascii_case(filter.as_bytes()))
    } else {
        label.to_lowercase().contains(filter)
    }
}

/// The rows to show, parents before children: collapsed subtrees hidden, or with a filter,
/// the matching rows and their ancestors (expanded).
fn visible_rows(state: &mut EditorState) -> Vec<Row> {
    let mut rows = std::mem::take(&mut state.hierarchy.rows);
    rows.clear();
    let mut tree = std::mem::take(&mut state.hierarchy.tree);
    let list = &state.entities;
    tree.build(list);
    let n = list.len();
    let filter = state.hierarchy.filter.to_lowercase();
    let shown: Option<Vec<bool>> = (!filter.is_empty()).then(|| {
        let mut shown = vec![false; n];
        for i in 0..n {
            if !matches(&state.row_label(i), &filter) {
                continue;
            }
            let mut at = Some(i);
            while let Some(row) = at {
                if shown[row] {
                    break;
                }
                shown[row] = true;
                at = list.parent(row);
            }
        }
        shown
    });
    let mut visited = vec![false; n];
    let mut stack: Vec<(usize, usize)> =
        tree.roots.iter().rev().map(|&r| (r as usize, 0)).collect();
    while let Some((index, depth)) = stack.pop() {
        if std::mem::replace(&mut visited[index], true) {
            continue; // a malformed list with a loop: show each row once
        }
        if shown.as_ref().is_some_and(|s| !s[index]) {
            continue;
        }
        let children = tree.children(index);
        rows.push(Row {
            index,
            depth,
            has_children: !children.is_empty(),
        });
        let entity = list.entities()[index];
        let open = shown.is_some() || !state.hierarchy.collapsed.contains(&entity);
        if open {
            stack.extend(children.iter().rev().map(|&c| (c as usize, depth + 1)));
        }
    }
    state.hierarchy.tree = tree;
    rows
}

/// What the user did in the panel this frame.
#[derive(Default)]
struct Actions {
    clicked: Option<(Entity, bool)>,
    start_rename: Option<Entity>,
    commit: Option<(Entity, String)>,
    toggle: Option<Entity>,
    /// An entity dropped onto another (`Some`) or onto the root area (`None`).
    dropped: Option<(Entity, Option<Entity>)>,
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

    let rows = visible_rows(state);
    let row_height = ui.spacing().interact_size.y;
    let mut actions = Actions::default();
    egui::ScrollArea::vertical()
        .auto_shrink([false, false])
        .max_height((ui.available_height() - 2.0 * row_height).max(row_height))
        .show_rows(ui, row_height, rows.len(), |ui, range| {
            for row in &rows[range] {
                row_ui(ui, state, *row, row_height, &mut actions);
            }
        });
    let (drop_area, drop) = ui.allocate_exact_size(
        egui::vec2(ui.available_width(), ui.available_height().max(row_height)),
        egui::Sense::hover(),
    );
    drop.widget_info(|| egui::WidgetInfo::labeled(egui::WidgetType::Other, true, ROOT_DROP_LABEL));
    if drop.dnd_hover_payload::<Entity>().is_some() {
        ui.painter().rect_stroke(
            drop_area,
            2.0,
            ui.visuals().selection.stroke,
            egui::StrokeKind::Inside,
        );
    }
    ui.painter().text(
        drop_area.left_top() + egui::vec2(4.0, 2.0),
        egui::Align2::LEFT_TOP,
        ROOT_DROP_LABEL,
        egui::TextStyle::Small.resolve(ui.style()),
        ui.visuals().weak_text_color(),
    );
    if let Some(dragged) = drop.dnd_release_payload::<Entity>() {
        actions.dropped = Some((*dragged, None));
    }
    state.hierarchy.rows = rows;
    apply(ui, ctx, state, actions);
}

fn row_ui(
    ui: &mut egui::Ui,
    state: &mut EditorState,
    row: Row,
    height: f32,
    actions: &mut Actions,
) {
    let Some(&entity) = state.entities.entities().get(row.index) else {
        return;
    };
    ui.horizontal(|ui| {
        ui.add_space(row.depth as f32 * INDENT);
        let label = state.row_label(row.index).into_owned();
        if row.has_children {
            let open = !state.hierarchy.collapsed.contains(&entity);
            let toggle = ui.add_sized(
                [TOGGLE_WIDTH, height],
                egui::Button::new(if open { "▼" } else { "▶" }).frame(false),
            );
            let name = format!("{} {label}", if open { "Collapse" } else { "Expand" });
            toggle.widget_info(|| egui::WidgetInfo::labeled(egui::WidgetType::Button, true, &name));
            if toggle.clicked() {
                actions.toggle = Some(entity);
            }
        } else {
            ui.add_space(TOGGLE_WIDTH + ui.spacing().item_spacing.x);
        }
        if let Some((renamed, text)) = &mut state.hierarchy.renaming {
            if *renamed == entity {
                let id = egui::Id::new(("hierarchy-rename", entity));
                let response = ui.add(
                    egui::TextEdit::singleline(text)
                        .id(id)
                        .desired_width(f32::INFINITY),
                );
                if !response.has_focus() && !response.lost_focus() {
                    response.request_focus();
                    // The field opens with the old name selected: typing replaces it.
                    // (Stored after the field drew: it stores its own state as it draws.)
                    let mut edit =
                        egui::text_edit::TextEditState::load(ui.ctx(), id).unwrap_or_default();
                    let all = egui::text::CCursorRange::two(
                        egui::text::CCursor::new(0),
                        egui::text::CCursor::new(text.chars().count()),
                    );
                    edit.cursor.set_char_range(Some(all));
                    edit.store(ui.ctx(), id);
                }
                if response.lost_focus() {
                    actions.commit = Some((entity, text.clone()));
                }
                return;
            }
        }
        let selected = state.selection.contains(&entity);
        // Dragging the row is a widget under the button that senses drags only: egui gives
        // the button its clicks and double-clicks and this one the drags.
        let rect =
            egui::Rect::from_min_size(ui.cursor().min, egui::vec2(ui.available_width(), height));
        let drag = ui.interact(
            rect,
            egui::Id::new(("hierarchy-row-drag", entity)),
            egui::Sense::drag(),
        );
        let response = ui.add(
            // The label, then room that grows: the name sits at the left, as in a tree.
            egui::Button::selectable(selected, (label.as_str(), egui::Atom::grow()))
                .min_size(rect.size()),
        );
        drag.dnd_set_drag_payload(entity);
        if response
            .dnd_hover_payload::<Entity>()
            .is_some_and(|e| *e != entity)
        {
            ui.painter().rect_stroke(
                response.rect,
                2.0,
                ui.visuals().selection.stroke,
                egui::StrokeKind::Inside,
            );
        }
        // A press on the row starts a drag at once (the drag widget senses nothing else), so
        // a plain click also "drops" the row onto itself: that is no drop.
        let dropped = response
            .dnd_release_payload::<Entity>()
            .filter(|dragged| **dragged != entity);
        if let Some(dragged) = dropped {
            actions.dropped = Some((*dragged, Some(entity)));
        } else if response.double_clicked() || response.triple_clicked() {
            // A click right after other clicks counts as a triple: still a rename.
            actions.start_rename = Some(entity);
        } else if response.clicked() {
            let multi = ui.input(|i| i.modifiers.command || i.modifiers.shift);
            actions.clicked = Some((entity, multi));
        }
    });
}

fn apply(ui: &egui::Ui, ctx: &mut Ctx, state: &mut EditorState, actions: Actions) {
    if let Some(entity) = actions.toggle {
        if !state.hierarchy.collapsed.remove(&entity) {
            state.hierarchy.collapsed.insert(entity);
        }
    }
    if let Some((entity, multi)) = actions.clicked {
        if multi {
            state.toggle_selected(entity);
        } else {
            state.select(entity);
        }
    }
    if let Some(entity) = actions.start_rename {
        let index = state.entities.entities().iter().position(|e| *e == entity);
        let name = index
            .map(|i| state.entities.name(i).to_owned())
            .unwrap_or_default();
        state.hierarchy.renaming = Some((entity, name));
        state.select(entity);
    }
    if let Some((entity, name)) = actions.commit {
        state.hierarchy.renaming = None;
        rename(ctx, state, entity, &name);
    }
    if let Some((dragged, target)) = actions.dropped {
        // Dragging one of the selected entities moves the whole selection.
        let moving = if state.selection.contains(&dragged) {
            state.selected_roots()
        } else {
            vec![dragged]
        };
        reparent(ctx, state, &moving, target);
        ui.ctx().request_repaint();
    }
}

/// Puts each of `entities` under `parent` (`None`: makes them roots), keeping where they are
/// in the world; one undo step. An entity that cannot go there (the parent is below it) is
/// reported and left where it is.
pub fn reparent(
    ctx: &mut Ctx,
    state: &mut EditorState,
    entities: &[Entity],
    parent: Option<Entity>,
) {
    let parent_key = ComponentKey::Builtin(BuiltinId::Parent);
    let transform_key = ComponentKey::Builtin(BuiltinId::Transform);
    let mut done = Vec::new();
    for &entity in entities {
        if Some(entity) == parent || ctx.parent(entity).ok().flatten() == parent {
            continue;
        }
        let old_parent = crate::history::component(ctx, entity, &parent_key);
        let old_transform = crate::history::component(ctx, entity, &transform_key);
        let moved = match parent {
            Some(p) => ctx.set_parent(entity, p, KeepPose::World),
            None => ctx.clear_parent(entity, KeepPose::World),
        };
        if let Err(e) = moved {
            state.report(ctx, "cannot move it there", e);
            continue;
        }
        // Undone last to first: the old local transform comes back, then the old parent
        // (which keeps it), so the entity ends exactly where it was.
        done.push(Command::SetComponent {
            entity,
            key: parent_key.clone(),
            old: old_parent,
            new: crate::history::component(ctx, entity, &parent_key),
        });
        done.push(Command::SetComponent {
            entity,
            key: transform_key.clone(),
            old: old_transform,
            new: crate::history::component(ctx, entity, &transform_key),
        });
    }
    if let Some(command) = Command::group(done) {
        state.record(ctx, command);
    }
}

/// Renames `entity` (undoable).
pub fn rename(ctx: &mut Ctx, state: &mut EditorState, entity: Entity, name: &str) {
    let key = ComponentKey::Builtin(BuiltinId::Name);
    let old = crate::history::component(ctx, entity, &key);
    let new = ComponentValue::Builtin(Name::new(name).into());
    if old.as_ref() == Some(&new) {
        return;
    }
    match ctx.set_component(entity, new.clone()) {
        Ok(()) => state.record(
            ctx,
            Command::SetComponent {
                entity,
                key,
                old,
                new: Some(new),
            },
        ),
        Err(e) => state.report(ctx, "cannot rename", e),
    }
}
