//! The Viewport panel: the host-rendered scene, the editor's fly camera, click-to-select,
//! view switches, the translate / rotate / scale gizmo (moving the whole selection), the
//! selection outline and the frame shown while playing.
//!
//! - `fly_camera.rs`: [`FlyCamera`], the editor camera's pose (kept over a reload).
//! - `gizmo.rs`: [`GizmoMode`], [`GizmoSpace`], the gizmo drawn on the primary selection and
//!   its drag of the whole selection.
//! - `overlays.rs`: the selection outline and the frame shown while playing.

mod fly_camera;
mod gizmo;
mod overlays;

pub use fly_camera::FlyCamera;
pub use gizmo::{GizmoMode, GizmoSpace, HANDLE_LABELS, SNAP_DEGREES, SNAP_METRES, SNAP_SCALE};

use onyx_plugin_api::glam::{EulerRot, Mat4, Quat, Vec2, Vec3, Vec4};
use onyx_plugin_api::tools::RenderOverrides;
use onyx_plugin_api::{egui, gui, Camera, Ctx, Entity, Name, ShadingMode, Transform};

use crate::state::EditorState;
use gizmo::GizmoDrag;

/// The name of the camera entity the editor drives.
pub const EDITOR_CAMERA: &str = "Editor Camera";
/// Vertical field of view of the editor camera, radians.
const FOV_Y: f32 = 0.8;
/// Fly speed, metres per second.
const FLY_SPEED: f32 = 6.0;
/// Radians per pixel of right-drag.
const LOOK_SPEED: f32 = 0.005;

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
    overlays::outline_selection(ui, ctx, state, &response, view_proj);
    let gizmo_took = gizmo::gizmo(ui, ctx, state, &response, view_proj);
    if response.clicked() && !gizmo_took {
        pick(ui, ctx, state, &response);
    }
    overlays::play_frame(ui, ctx, rect);
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
