//! What the viewport draws over the scene: the selection outline, and the frame shown while
//! playing.

use onyx_plugin_api::glam::Mat4;
use onyx_plugin_api::tools::Bounds;
use onyx_plugin_api::{egui, Ctx, PlayMode};

use super::to_screen;
use crate::state::EditorState;

/// The outline of the primary selection.
const OUTLINE: egui::Color32 = egui::Color32::from_rgb(255, 170, 0);
/// The outline of the rest of the selection.
const OUTLINE_OTHERS: egui::Color32 = egui::Color32::from_rgb(255, 220, 140);
/// The frame around the viewport while playing or paused.
const PLAYING_FRAME: egui::Color32 = egui::Color32::from_rgb(255, 140, 0);
/// Its width, points.
const PLAYING_FRAME_WIDTH: f32 = 3.0;

/// While playing or paused: a frame around the view and a line saying Stop puts the scene
/// back, so a change made now is not mistaken for an edit.
pub(super) fn play_frame(ui: &mut egui::Ui, ctx: &mut Ctx, rect: egui::Rect) {
    let mode = ctx.play_mode();
    let what = match mode {
        PlayMode::Edit => return,
        PlayMode::Playing => "Playing: Stop puts the scene back",
        PlayMode::Paused => "Paused: Stop puts the scene back",
    };
    ui.painter_at(rect).rect_stroke(
        rect,
        0.0,
        egui::Stroke::new(PLAYING_FRAME_WIDTH, PLAYING_FRAME),
        egui::StrokeKind::Inside,
    );
    let at = egui::Rect::from_min_size(
        rect.min + egui::vec2(PLAYING_FRAME_WIDTH + 6.0, PLAYING_FRAME_WIDTH + 4.0),
        egui::vec2(rect.width() - 2.0 * (PLAYING_FRAME_WIDTH + 6.0), 20.0),
    );
    let text = egui::RichText::new(what)
        .color(PLAYING_FRAME)
        .background_color(egui::Color32::from_black_alpha(160));
    ui.put(at, egui::Label::new(text).selectable(false));
}

/// Outlines each selected entity: the edges of the box around what it shows, at its world
/// pose (the primary brighter). Each outline is named for AccessKit ("Selection outline:
/// NAME"), over the screen rectangle it covers.
pub(super) fn outline_selection(
    ui: &mut egui::Ui,
    ctx: &mut Ctx,
    state: &EditorState,
    response: &egui::Response,
    view_proj: Mat4,
) {
    let rect = response.rect;
    let painter = ui.painter_at(rect);
    let primary = state.primary();
    for &entity in &state.selection {
        if Some(entity) == state.viewport.entity {
            continue;
        }
        let (Some(bounds), Ok(pose)) = (ctx.local_bounds(entity), ctx.world_pose(entity)) else {
            continue;
        };
        let corners = outline_corners(&bounds, pose.0.into(), view_proj, rect);
        let colour = if Some(entity) == primary {
            OUTLINE
        } else {
            OUTLINE_OTHERS
        };
        let stroke = egui::Stroke::new(2.0, colour);
        let mut covered: Option<egui::Rect> = None;
        for (a, b) in Bounds::EDGES {
            if let (Some(a), Some(b)) = (corners[a], corners[b]) {
                painter.line_segment([a, b], stroke);
                let edge = egui::Rect::from_two_pos(a, b);
                covered = Some(covered.map_or(edge, |c| c.union(edge)));
            }
        }
        let Some(covered) = covered
            .map(|c| c.intersect(rect))
            .filter(|c| c.is_positive())
        else {
            continue;
        };
        let name = state
            .entities
            .entities()
            .iter()
            .position(|e| *e == entity)
            .map(|row| state.row_label(row).into_owned())
            .unwrap_or_default();
        let node = ui.interact(
            covered,
            response.id.with(("selection-outline", entity)),
            egui::Sense::hover(),
        );
        node.widget_info(|| {
            egui::WidgetInfo::labeled(
                egui::WidgetType::Other,
                true,
                format!("Selection outline: {name}"),
            )
        });
    }
}

/// The screen positions of the corners of `bounds` placed at `pose` (`None` behind the eye).
fn outline_corners(
    bounds: &Bounds,
    pose: Mat4,
    view_proj: Mat4,
    rect: egui::Rect,
) -> [Option<egui::Pos2>; 8] {
    bounds
        .corners()
        .map(|c| to_screen(view_proj, rect, pose.transform_point3(c)))
}
