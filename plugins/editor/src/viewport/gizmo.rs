//! The gizmo: move / rotate / scale handles on the primary selection, dragged in world or
//! local axes (Ctrl snaps), moving every selected subtree once as one undo step.

use onyx_plugin_api::glam::{Mat4, Quat, Vec2, Vec3};
use onyx_plugin_api::tools::{ComponentKey, ComponentValue};
use onyx_plugin_api::{egui, BuiltinId, Ctx, Entity, Transform};

use super::to_screen;
use crate::history::Command;
use crate::state::EditorState;

/// Gizmo axis length on screen, as a share of the distance to the camera.
const GIZMO_SCALE: f32 = 0.15;
/// With Ctrl held, moves snap to multiples of this, metres.
pub const SNAP_METRES: f32 = 0.5;
/// With Ctrl held, turns snap to multiples of this, degrees.
pub const SNAP_DEGREES: f32 = 15.0;
/// With Ctrl held, scales snap to multiples of this.
pub const SNAP_SCALE: f32 = 0.1;
/// How near (points) to an axis handle a press must be to grab it.
const GRAB_DISTANCE: f32 = 10.0;

/// Which gizmo the selection shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GizmoMode {
    /// Move along an axis (W).
    #[default]
    Translate,
    /// Turn about an axis (E).
    Rotate,
    /// Scale along an axis (R).
    Scale,
}

/// Which axes the gizmo moves and turns along. Scaling is always along the object's own axes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GizmoSpace {
    /// The world's X, Y, Z.
    #[default]
    World,
    /// The selection's own (rotated) axes.
    Local,
}

/// An entity a gizmo drag moves: a selected entity with no selected ancestor.
#[derive(Clone, Debug)]
struct Mover {
    entity: Entity,
    /// Its world pose when the drag started.
    start: Transform,
    /// Its local transform (its component) when the drag started, for undo.
    old: Option<ComponentValue>,
}

#[derive(Clone, Debug)]
pub(super) struct GizmoDrag {
    /// The primary selection, whose gizmo is dragged.
    entity: Entity,
    axis: usize,
    /// The primary's world pose when the drag started.
    start: Transform,
    moved: Vec2,
    screen_axis: Vec2,
    world_length: f32,
    /// Everything the drag moves (the whole selection, each subtree once).
    movers: Vec<Mover>,
}

/// The gizmo handles' accessible names, by axis.
pub const HANDLE_LABELS: [&str; 3] = ["Gizmo X", "Gizmo Y", "Gizmo Z"];

const AXES: [(Vec3, egui::Color32); 3] = [
    (Vec3::X, egui::Color32::from_rgb(230, 70, 70)),
    (Vec3::Y, egui::Color32::from_rgb(80, 210, 80)),
    (Vec3::Z, egui::Color32::from_rgb(70, 120, 240)),
];

/// Draws the gizmo of the primary selection and drags the whole selection with it (each
/// selected subtree once, as one undo step); whether the pointer used it.
pub(super) fn gizmo(
    ui: &mut egui::Ui,
    ctx: &mut Ctx,
    state: &mut EditorState,
    response: &egui::Response,
    view_proj: Mat4,
) -> bool {
    let rect = response.rect;
    let Some(entity) = state.primary() else {
        state.viewport.drag = None;
        return false;
    };
    if Some(entity) == state.viewport.entity {
        return false;
    }
    // The gizmo works in world space; the entity's local transform is written back.
    let Ok(transform) = ctx.world_pose(entity).map(|pose| pose.to_transform()) else {
        return false;
    };
    let origin = transform.translation;
    let cam_pos = Vec3::from_array(state.viewport.camera.position);
    let world_length = (origin.distance(cam_pos) * GIZMO_SCALE).max(0.01);
    let Some(center) = to_screen(view_proj, rect, origin) else {
        return false;
    };
    let painter = ui.painter_at(rect);
    let mode = state.viewport.gizmo;
    let local = mode == GizmoMode::Scale || state.viewport.space == GizmoSpace::Local;
    let axis_direction = |axis: Vec3, rotation: Quat| if local { rotation * axis } else { axis };
    let mut ends = Vec::new();
    for (axis, (dir, color)) in AXES.iter().enumerate() {
        let dir = axis_direction(*dir, transform.rotation);
        let Some(end) = to_screen(view_proj, rect, origin + dir * world_length) else {
            continue;
        };
        let active = state.viewport.drag.as_ref().is_some_and(|d| d.axis == axis);
        let stroke = egui::Stroke::new(if active { 4.0 } else { 2.5 }, *color);
        painter.line_segment([center, end], stroke);
        match mode {
            GizmoMode::Translate => {
                painter.circle_filled(end, 5.0, *color);
            }
            GizmoMode::Rotate => {
                painter.circle_stroke(end, 6.0, stroke);
            }
            GizmoMode::Scale => {
                painter.rect_filled(
                    egui::Rect::from_center_size(end, egui::vec2(9.0, 9.0)),
                    0.0,
                    *color,
                );
            }
        }
        // Each handle is a named node for AccessKit (screen readers, and tests that grab
        // the handle by name); it only senses hover, so the drag stays the viewport's.
        let handle = ui.interact(
            egui::Rect::from_center_size(end, egui::Vec2::splat(2.0 * GRAB_DISTANCE)),
            response.id.with(("gizmo-handle", axis)),
            egui::Sense::hover(),
        );
        handle.widget_info(|| {
            egui::WidgetInfo::labeled(egui::WidgetType::Other, true, HANDLE_LABELS[axis])
        });
        ends.push((axis, end));
    }

    let mut took = false;
    if response.drag_started_by(egui::PointerButton::Primary) {
        // Where the button went down: the drag starts only after the pointer has travelled.
        let pressed_at = ui.input(|i| i.pointer.press_origin());
        if let Some(pointer) = pressed_at.or(response.interact_pointer_pos()) {
            let nearest = ends
                .iter()
                .map(|(axis, end)| (*axis, *end, distance_to_segment(pointer, center, *end)))
                .filter(|(_, _, d)| *d < GRAB_DISTANCE)
                .min_by(|a, b| a.2.total_cmp(&b.2));
            if let Some((axis, end, _)) = nearest {
                let screen = end - center;
                let mut movers = Vec::new();
                for root in state.selected_roots() {
                    let Ok(start) = ctx.world_pose(root).map(|pose| pose.to_transform()) else {
                        continue;
                    };
                    let old = crate::history::component(ctx, root, &TRANSFORM);
                    movers.push(Mover {
                        entity: root,
                        start,
                        old,
                    });
                }
                state.viewport.drag = Some(GizmoDrag {
                    entity,
                    axis,
                    start: transform,
                    moved: Vec2::ZERO,
                    screen_axis: Vec2::new(screen.x, screen.y),
                    world_length,
                    movers,
                });
                took = true;
            }
        }
    }
    if let Some(drag) = &mut state.viewport.drag {
        took = true;
        if drag.entity != entity {
            state.viewport.drag = None;
            return took;
        }
        let delta = response.drag_delta();
        drag.moved += Vec2::new(delta.x, delta.y);
        let snap = ui.input(|i| i.modifiers.command || i.modifiers.ctrl);
        let t = dragged(
            drag,
            mode,
            axis_direction(AXES[drag.axis].0, drag.start.rotation),
            snap,
        );
        if t.is_finite() {
            for mover in &drag.movers {
                let moved = carried(&drag.start, &t, &mover.start, mode);
                if moved.is_finite() {
                    let _ = ctx.set_world_pose(mover.entity, moved);
                }
            }
        }
        if response.drag_stopped() || !ui.input(|i| i.pointer.primary_down()) {
            let finished = state.viewport.drag.take();
            if let Some(drag) = finished {
                let mut edits = Vec::new();
                for mover in drag.movers {
                    let new = crate::history::component(ctx, mover.entity, &TRANSFORM);
                    if new != mover.old {
                        edits.push(Command::SetComponent {
                            entity: mover.entity,
                            key: TRANSFORM,
                            old: mover.old,
                            new,
                        });
                    }
                }
                if let Some(command) = Command::group(edits) {
                    state.record(ctx, command);
                }
            }
        }
    }
    took
}

/// The transform `drag` gives: along `axis` (world or local, as drawn) by the pointer's
/// travel along the handle on screen, snapped when `snap`.
fn dragged(drag: &GizmoDrag, mode: GizmoMode, axis: Vec3, snap: bool) -> Transform {
    let len = drag.screen_axis.length().max(1.0);
    let along = drag.moved.dot(drag.screen_axis / len) / len;
    let snapped = |value: f32, step: f32| {
        if snap {
            (value / step).round() * step
        } else {
            value
        }
    };
    let mut t = drag.start;
    match mode {
        GizmoMode::Translate => {
            let distance = snapped(along * drag.world_length, SNAP_METRES);
            t.translation += axis * distance;
        }
        GizmoMode::Rotate => {
            // Dragging across the handle turns about it: 0.5° per point.
            let degrees = snapped(
                drag.moved.perp_dot(drag.screen_axis / len) * 0.5,
                SNAP_DEGREES,
            );
            t.rotation = (Quat::from_axis_angle(axis, degrees.to_radians()) * drag.start.rotation)
                .normalize();
        }
        GizmoMode::Scale => {
            let mut s = t.scale.to_array();
            s[drag.axis] = snapped(s[drag.axis] * (1.0 + along), SNAP_SCALE).max(0.01);
            t.scale = Vec3::from_array(s);
        }
    }
    t
}

/// Where the gizmo drag that took the primary from `from` to `to` (world poses) takes
/// another selected entity that was at `other`: moved by the same offset, turned about the
/// primary's origin by the same turn, or scaled along its own axes by the same factors.
fn carried(from: &Transform, to: &Transform, other: &Transform, mode: GizmoMode) -> Transform {
    let mut t = *other;
    match mode {
        GizmoMode::Translate => t.translation += to.translation - from.translation,
        GizmoMode::Rotate => {
            let turn = to.rotation * from.rotation.inverse();
            t.translation = from.translation + turn * (other.translation - from.translation);
            t.rotation = (turn * other.rotation).normalize();
        }
        GizmoMode::Scale => {
            let factor = to.scale / from.scale.max(Vec3::splat(1e-6));
            t.scale = (other.scale * factor).max(Vec3::splat(0.01));
        }
    }
    t
}

fn distance_to_segment(p: egui::Pos2, a: egui::Pos2, b: egui::Pos2) -> f32 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.length_sq().max(1e-6)).clamp(0.0, 1.0);
    (a + ab * t).distance(p)
}

/// The key of the `Transform` component.
const TRANSFORM: ComponentKey = ComponentKey::Builtin(BuiltinId::Transform);
