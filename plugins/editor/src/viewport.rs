//! The Viewport panel: the host-rendered scene, the editor's fly camera, click-to-select,
//! view switches, the translate / rotate / scale gizmo (moving the whole selection), the
//! selection outline and the frame shown while playing.

use onyx_plugin_api::glam::{EulerRot, Mat4, Quat, Vec2, Vec3, Vec4};
use onyx_plugin_api::tools::{Bounds, ComponentKey, ComponentValue, RenderOverrides};
use onyx_plugin_api::{
    egui, gui, BuiltinId, Camera, Ctx, Entity, Name, PlayMode, ShadingMode, Transform,
};
use serde::{Deserialize, Serialize};

use crate::history::Command;
use crate::state::EditorState;

/// The name of the camera entity the editor drives.
pub const EDITOR_CAMERA: &str = "Editor Camera";
/// Vertical field of view of the editor camera, radians.
const FOV_Y: f32 = 0.8;
/// Fly speed, metres per second.
const FLY_SPEED: f32 = 6.0;
/// Radians per pixel of right-drag.
const LOOK_SPEED: f32 = 0.005;
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
/// The outline of the primary selection.
const OUTLINE: egui::Color32 = egui::Color32::from_rgb(255, 170, 0);
/// The outline of the rest of the selection.
const OUTLINE_OTHERS: egui::Color32 = egui::Color32::from_rgb(255, 220, 140);
/// The frame around the viewport while playing or paused.
const PLAYING_FRAME: egui::Color32 = egui::Color32::from_rgb(255, 140, 0);
/// Its width, points.
const PLAYING_FRAME_WIDTH: f32 = 3.0;

/// The editor camera's pose.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FlyCamera {
    /// Position, metres.
    pub position: [f32; 3],
    /// Turn about Y, radians.
    pub yaw: f32,
    /// Tilt, radians (negative looks down).
    pub pitch: f32,
}

impl Default for FlyCamera {
    fn default() -> Self {
        Self {
            position: [0.0, 4.0, 10.0],
            yaw: 0.0,
            pitch: -0.35,
        }
    }
}

impl FlyCamera {
    fn rotation(&self) -> Quat {
        Quat::from_euler(EulerRot::YXZ, self.yaw, self.pitch, 0.0)
    }

    /// Unit direction the camera looks along.
    pub fn forward(&self) -> Vec3 {
        self.rotation() * Vec3::NEG_Z
    }

    /// The camera entity's transform.
    pub fn transform(&self) -> Transform {
        Transform::from_translation(Vec3::from_array(self.position)).with_rotation(self.rotation())
    }
}

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
struct GizmoDrag {
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

/// The viewport's state.
#[derive(Debug)]
pub struct ViewportState {
    /// The fly camera's pose.
    pub camera: FlyCamera,
    entity: Option<Entity>,
    written: Option<Transform>,
    /// The gizmo shown.
    pub gizmo: GizmoMode,
    /// World or local axes.
    pub space: GizmoSpace,
    drag: Option<GizmoDrag>,
    /// Grid on.
    pub grid: bool,
    /// Physics debug lines on.
    pub physics_debug: bool,
    /// Shading of the whole view (`None`: each object's own).
    pub shading: Option<ShadingMode>,
    overrides_sent: Option<RenderOverrides>,
}

impl Default for ViewportState {
    fn default() -> Self {
        Self {
            camera: FlyCamera::default(),
            entity: None,
            written: None,
            gizmo: GizmoMode::default(),
            space: GizmoSpace::default(),
            drag: None,
            grid: true,
            physics_debug: false,
            shading: None,
            overrides_sent: None,
        }
    }
}

impl ViewportState {
    /// Finds (by name, among cameras) or makes the editor camera entity, makes it the view
    /// and moves it to the fly camera's pose. The entity is checked to still be a camera
    /// each frame: a handle kept across a new or opened scene must never steer anything else.
    pub fn ensure_camera(&mut self, ctx: &mut Ctx) {
        let alive = self.entity.is_some_and(|e| ctx.get::<Camera>(e).is_ok());
        if !alive {
            let list = ctx.entity_list();
            let named: Vec<Entity> = list
                .iter()
                .filter(|(_, name)| *name == EDITOR_CAMERA)
                .map(|(e, _)| e)
                .collect();
            let found = named.into_iter().find(|e| ctx.get::<Camera>(*e).is_ok());
            let entity = match found {
                Some(e) => Some(e),
                None => ctx
                    .spawn((
                        Name::new(EDITOR_CAMERA),
                        self.camera.transform(),
                        Camera::perspective(FOV_Y),
                    ))
                    .ok(),
            };
            if let Some(e) = entity {
                if let Err(error) = ctx.set_camera(e) {
                    ctx.warn(format!("cannot look through the editor camera: {error}"));
                }
            }
            self.entity = entity;
            self.written = None;
        }
        let transform = self.camera.transform();
        if let Some(e) = self.entity {
            if self.written != Some(transform) && ctx.set(e, transform).is_ok() {
                self.written = Some(transform);
            }
        }
        let overrides = self.overrides();
        if self.overrides_sent != Some(overrides) {
            ctx.set_render_overrides(overrides);
            self.overrides_sent = Some(overrides);
        }
    }

    /// The editor camera entity.
    pub fn camera_entity(&self) -> Option<Entity> {
        self.entity
    }

    /// Forgets the camera entity (the world was replaced): the next frame finds or makes it
    /// again.
    pub fn forget_camera(&mut self) {
        self.entity = None;
        self.written = None;
        self.drag = None;
    }

    fn overrides(&self) -> RenderOverrides {
        let overrides = RenderOverrides::default()
            .with_grid(self.grid)
            .with_physics_debug(self.physics_debug);
        match self.shading {
            Some(mode) => overrides.with_shading(mode),
            None => overrides,
        }
    }

    /// Where Create puts a new entity: 5 m in front of the camera, on the ground.
    pub fn spawn_point(&self) -> Vec3 {
        let p = Vec3::from_array(self.camera.position) + self.camera.forward() * 5.0;
        Vec3::new(p.x, p.y.max(0.5), p.z)
    }
}

/// The accessible name of the viewport image.
pub const VIEWPORT_LABEL: &str = "Scene viewport";

/// Draws the panel.
pub fn show(ui: &mut egui::Ui, ctx: &mut Ctx, state: &mut EditorState) {
    toolbar(ui, &mut state.viewport);
    let response = gui::viewport(ui);
    response
        .widget_info(|| egui::WidgetInfo::labeled(egui::WidgetType::Image, true, VIEWPORT_LABEL));
    let rect = response.rect;
    fly(ui, ctx, state, &response);
    let view_proj = view_projection(&state.viewport.camera, rect);
    outline_selection(ui, ctx, state, &response, view_proj);
    let gizmo_took = gizmo(ui, ctx, state, &response, view_proj);
    if response.clicked() && !gizmo_took {
        pick(ui, ctx, state, &response);
    }
    play_frame(ui, ctx, rect);
}

/// While playing or paused: a frame around the view and a line saying Stop puts the scene
/// back, so a change made now is not mistaken for an edit.
fn play_frame(ui: &mut egui::Ui, ctx: &mut Ctx, rect: egui::Rect) {
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
fn outline_selection(
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

fn toolbar(ui: &mut egui::Ui, view: &mut ViewportState) {
    ui.horizontal(|ui| {
        ui.checkbox(&mut view.grid, "Grid");
        ui.checkbox(&mut view.physics_debug, "Physics debug");
        egui::ComboBox::from_id_salt("view-shading")
            .selected_text(match view.shading {
                Some(mode) => format!("{mode:?}"),
                None => "Materials".to_owned(),
            })
            .show_ui(ui, |ui| {
                ui.selectable_value(&mut view.shading, None, "Materials");
                for mode in [
                    ShadingMode::Unlit,
                    ShadingMode::LitLow,
                    ShadingMode::Lit,
                    ShadingMode::Normal,
                    ShadingMode::Wireframe,
                ] {
                    ui.selectable_value(&mut view.shading, Some(mode), format!("{mode:?}"));
                }
            });
        ui.separator();
        ui.selectable_value(&mut view.gizmo, GizmoMode::Translate, "Move (W)");
        ui.selectable_value(&mut view.gizmo, GizmoMode::Rotate, "Rotate (E)");
        ui.selectable_value(&mut view.gizmo, GizmoMode::Scale, "Scale (R)");
        ui.separator();
        ui.selectable_value(&mut view.space, GizmoSpace::World, "World");
        ui.selectable_value(&mut view.space, GizmoSpace::Local, "Local");
        ui.weak("Ctrl snaps");
    });
}

/// Right mouse + WASD/QE flies, the wheel zooms, F focuses the selection, W/E/R pick the gizmo.
fn fly(ui: &mut egui::Ui, ctx: &mut Ctx, state: &mut EditorState, response: &egui::Response) {
    let hovered = response.hovered();
    let cam = &mut state.viewport.camera;
    let (looking, delta, dt, scroll) = ui.input(|i| {
        (
            i.pointer.secondary_down(),
            i.pointer.delta(),
            i.stable_dt.min(0.1),
            i.smooth_scroll_delta.y,
        )
    });
    let looking = looking && (hovered || response.dragged_by(egui::PointerButton::Secondary));
    if looking {
        cam.yaw -= delta.x * LOOK_SPEED;
        cam.pitch = (cam.pitch - delta.y * LOOK_SPEED).clamp(-1.55, 1.55);
        let rotation = Quat::from_euler(EulerRot::YXZ, cam.yaw, cam.pitch, 0.0);
        let mut step = Vec3::ZERO;
        ui.input(|i| {
            for (key, dir) in [
                (egui::Key::W, Vec3::NEG_Z),
                (egui::Key::S, Vec3::Z),
                (egui::Key::A, Vec3::NEG_X),
                (egui::Key::D, Vec3::X),
                (egui::Key::E, Vec3::Y),
                (egui::Key::Q, Vec3::NEG_Y),
            ] {
                if i.key_down(key) {
                    step += dir;
                }
            }
        });
        let fast = if ui.input(|i| i.modifiers.shift) {
            3.0
        } else {
            1.0
        };
        let moved = rotation * step * FLY_SPEED * fast * dt;
        cam.position = (Vec3::from_array(cam.position) + moved).to_array();
    } else if hovered && !ui.ctx().egui_wants_keyboard_input() {
        ui.input(|i| {
            if i.key_pressed(egui::Key::W) {
                state.viewport.gizmo = GizmoMode::Translate;
            }
            if i.key_pressed(egui::Key::E) {
                state.viewport.gizmo = GizmoMode::Rotate;
            }
            if i.key_pressed(egui::Key::R) {
                state.viewport.gizmo = GizmoMode::Scale;
            }
        });
    }
    if hovered && scroll != 0.0 {
        let cam = &mut state.viewport.camera;
        let moved = cam.forward() * scroll * 0.01;
        cam.position = (Vec3::from_array(cam.position) + moved).to_array();
    }
    let focus = hovered && ui.input(|i| i.key_pressed(egui::Key::F));
    if focus {
        let target = state
            .primary()
            .and_then(|e| ctx.world_pose(e).ok())
            .map(|pose| pose.to_transform());
        if let Some(target) = target {
            let cam = &mut state.viewport.camera;
            let distance = 3.0 + target.scale.max_element() * 2.0;
            cam.position = (target.translation - cam.forward() * distance).to_array();
        }
    }
}

fn view_projection(cam: &FlyCamera, rect: egui::Rect) -> Mat4 {
    let aspect = (rect.width() / rect.height().max(1.0)).max(0.01);
    // Right-handed, depth 0..1 (wgpu), as the renderer builds it.
    let (near, far) = (0.1f32, 1000.0f32);
    let f = 1.0 / (FOV_Y * 0.5).tan();
    let range = far / (near - far);
    let proj = Mat4::from_cols(
        Vec4::new(f / aspect, 0.0, 0.0, 0.0),
        Vec4::new(0.0, f, 0.0, 0.0),
        Vec4::new(0.0, 0.0, range, -1.0),
        Vec4::new(0.0, 0.0, range * near, 0.0),
    );
    proj * cam.transform().matrix().inverse()
}

fn to_screen(view_proj: Mat4, rect: egui::Rect, p: Vec3) -> Option<egui::Pos2> {
    let clip = view_proj * p.extend(1.0);
    if clip.w <= 1e-4 {
        return None;
    }
    let ndc = clip.truncate() / clip.w;
    Some(egui::pos2(
        rect.min.x + (ndc.x + 1.0) * 0.5 * rect.width(),
        rect.min.y + (1.0 - ndc.y) * 0.5 * rect.height(),
    ))
}

fn pick(ui: &mut egui::Ui, ctx: &mut Ctx, state: &mut EditorState, response: &egui::Response) {
    let Some(pointer) = response.interact_pointer_pos() else {
        return;
    };
    let ppp = ui.ctx().pixels_per_point();
    let local = (pointer - response.rect.min) * ppp;
    let size = response.rect.size() * ppp;
    let ray = ctx
        .screen_ray(Vec2::new(local.x, local.y), Vec2::new(size.x, size.y))
        .map(|r| (r.origin, r.direction))
        .unwrap_or_else(|| own_ray(&state.viewport.camera, response.rect, pointer));
    // What each entity shows — meshes and colliders, at world poses — nearest first.
    let hit = ctx
        .pick(ray.0, ray.1, 1000.0)
        .map(|h| h.entity)
        .filter(|e| Some(*e) != state.viewport.entity);
    let multi = ui.input(|i| i.modifiers.command || i.modifiers.shift);
    match hit {
        Some(hit) if multi => state.toggle_selected(hit),
        Some(hit) => state.select(hit),
        None if !multi => state.selection.clear(),
        None => {}
    }
}

/// The ray through `pointer` seen through the fly camera.
fn own_ray(cam: &FlyCamera, rect: egui::Rect, pointer: egui::Pos2) -> (Vec3, Vec3) {
    let inverse = view_projection(cam, rect).inverse();
    let ndc_x = (pointer.x - rect.min.x) / rect.width().max(1.0) * 2.0 - 1.0;
    let ndc_y = 1.0 - (pointer.y - rect.min.y) / rect.height().max(1.0) * 2.0;
    let near = inverse.project_point3(Vec3::new(ndc_x, ndc_y, 0.0));
    let far = inverse.project_point3(Vec3::new(ndc_x, ndc_y, 1.0));
    (near, (far - near).normalize_or(Vec3::NEG_Z))
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
fn gizmo(
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
