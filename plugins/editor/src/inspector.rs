//! The Inspector panel: the selection's name and every component, with fitting widgets for
//! the built-ins and a JSON tree for plugin components; add and remove components.

use onyx_plugin_api::glam::{EulerRot, Quat, Vec3};
use onyx_plugin_api::tools::ComponentEntry;
use onyx_plugin_api::{
    egui, BodyKind, Camera, Collider, ColliderShape, Ctx, Entity, Light, MeshRenderer, Projection,
    RigidBody, Script, ShadingMode, Transform,
};
use serde::de::DeserializeOwned;
use serde::Serialize;

use crate::history::Command;
use crate::state::EditorState;

/// Built-in components the Add Component menu offers.
const ADDABLE: [&str; 7] = [
    "Transform",
    "MeshRenderer",
    "Camera",
    "Light",
    "RigidBody",
    "Collider",
    "onyx.Script",
];

/// The inspector's own state.
#[derive(Debug, Default)]
pub struct InspectorState {
    /// The name being typed, for which entity.
    name: Option<(Entity, String)>,
}

/// Draws the panel.
pub fn show(ui: &mut egui::Ui, ctx: &mut Ctx, state: &mut EditorState) {
    let Some(entity) = state.primary() else {
        ui.weak("Nothing selected");
        return;
    };
    let components = match ctx.components_of(entity) {
        Ok(c) => c,
        Err(e) => {
            ui.colored_label(egui::Color32::LIGHT_RED, e.to_string());
            return;
        }
    };
    if state.selection.len() > 1 {
        ui.weak(format!(
            "{} selected; showing the last",
            state.selection.len()
        ));
    }
    name_field(ui, ctx, state, entity, &components);
    ui.weak(format!("entity {entity}"));
    ui.separator();

    let mut edits: Vec<(String, Option<String>, Option<String>)> = Vec::new();
    egui::ScrollArea::vertical()
        .auto_shrink([false, false])
        .show(ui, |ui| {
            for entry in components.iter().filter(|c| c.type_name != "Name") {
                let id = egui::Id::new(("inspector", entity, entry.type_name.as_str()));
                let mut remove = false;
                let mut new = None;
                egui::CollapsingHeader::new(entry.type_name.as_str())
                    .id_salt(id)
                    .default_open(true)
                    .show(ui, |ui| {
                        new = component_ui(ui, ctx, entry, id);
                        if ui
                            .small_button(format!("Remove {}", entry.type_name))
                            .clicked()
                        {
                            remove = true;
                        }
                    });
                if remove {
                    edits.push((entry.type_name.clone(), Some(entry.value.clone()), None));
                } else if let Some(new) = new {
                    edits.push((
                        entry.type_name.clone(),
                        Some(entry.value.clone()),
                        Some(new),
                    ));
                }
            }
            ui.separator();
            ui.menu_button("Add Component", |ui| {
                for name in ADDABLE {
                    let present = components.iter().any(|c| c.type_name == name);
                    if ui.add_enabled(!present, egui::Button::new(name)).clicked() {
                        edits.push((name.to_owned(), None, None));
                    }
                }
            });
        });

    for (type_name, old, new) in edits {
        let result = match (&old, &new) {
            (None, _) => ctx.add_component(entity, &type_name),
            (Some(_), None) => ctx.remove_component(entity, &type_name),
            (Some(_), Some(json)) => ctx.set_component_json(entity, &type_name, json),
        };
        match result {
            Ok(()) => {
                let new = if old.is_none() {
                    current(ctx, entity, &type_name)
                } else {
                    new
                };
                let command = Command::SetComponent {
                    entity,
                    type_name,
                    old: old.clone(),
                    new,
                };
                if old.is_some() && command_is_set(&command) {
                    state.record_merged(ctx, command);
                } else {
                    state.record(ctx, command);
                }
            }
            Err(e) => state.report(ctx, &format!("cannot edit {type_name}"), e),
        }
    }
}

fn command_is_set(command: &Command) -> bool {
    matches!(command, Command::SetComponent { new: Some(_), .. })
}

fn current(ctx: &mut Ctx, entity: Entity, type_name: &str) -> Option<String> {
    ctx.components_of(entity)
        .ok()?
        .into_iter()
        .find(|c| c.type_name == type_name)
        .map(|c| c.value)
}

fn name_field(
    ui: &mut egui::Ui,
    ctx: &mut Ctx,
    state: &mut EditorState,
    entity: Entity,
    components: &[ComponentEntry],
) {
    let current: String = components
        .iter()
        .find(|c| c.type_name == "Name")
        .and_then(|c| serde_json::from_str(&c.value).ok())
        .unwrap_or_default();
    let id = egui::Id::new("inspector-name");
    let focused = ui.ctx().memory(|m| m.has_focus(id));
    let buffer = match &mut state.inspector.name {
        Some((e, text)) if *e == entity && focused => text,
        slot => &mut slot.insert((entity, current.clone())).1,
    };
    let mut commit = None;
    ui.horizontal(|ui| {
        ui.label("Name");
        let response = ui.add(egui::TextEdit::singleline(buffer).id(id));
        if response.lost_focus() && *buffer != current {
            commit = Some(buffer.clone());
        }
    });
    if let Some(name) = commit {
        crate::hierarchy::rename(ctx, state, entity, &name);
    }
}

/// The widgets of one component; the new JSON when the user changed it.
fn component_ui(
    ui: &mut egui::Ui,
    ctx: &mut Ctx,
    entry: &ComponentEntry,
    id: egui::Id,
) -> Option<String> {
    match entry.type_name.as_str() {
        "Transform" => typed(ui, &entry.value, transform_ui),
        "MeshRenderer" => typed(ui, &entry.value, mesh_renderer_ui),
        "Light" => typed(ui, &entry.value, light_ui),
        "Camera" => typed(ui, &entry.value, camera_ui),
        "RigidBody" => typed(ui, &entry.value, rigid_body_ui),
        "Collider" => typed(ui, &entry.value, collider_ui),
        "onyx.Script" => {
            let scripts = ctx.registered_scripts();
            typed(ui, &entry.value, |ui, script: &mut Script| {
                egui::ComboBox::from_id_salt(id.with("script"))
                    .selected_text(if script.name.is_empty() {
                        "(none)"
                    } else {
                        script.name.as_str()
                    })
                    .show_ui(ui, |ui| {
                        for info in &scripts {
                            if ui
                                .selectable_label(script.name == info.name, &info.name)
                                .clicked()
                                && script.name != info.name
                            {
                                script.name = info.name.clone();
                                script.params = info.default_params.clone();
                            }
                        }
                    });
                crate::json_tree::edit(ui, "params", &mut script.params, id.with("params"));
            })
        }
        _ => {
            let mut value: serde_json::Value = serde_json::from_str(&entry.value).ok()?;
            if crate::json_tree::edit(ui, "", &mut value, id) {
                Some(value.to_string())
            } else {
                None
            }
        }
    }
}

/// Decodes, edits and re-encodes a typed component; `Some(json)` when it changed.
fn typed<T>(
    ui: &mut egui::Ui,
    json: &str,
    edit: impl FnOnce(&mut egui::Ui, &mut T),
) -> Option<String>
where
    T: DeserializeOwned + Serialize + PartialEq + Clone,
{
    let original: T = match serde_json::from_str(json) {
        Ok(v) => v,
        Err(e) => {
            ui.colored_label(egui::Color32::LIGHT_RED, e.to_string());
            return None;
        }
    };
    let mut value = original.clone();
    edit(ui, &mut value);
    (value != original)
        .then(|| serde_json::to_string(&value).ok())
        .flatten()
}

/// A colour button that writes back only what the user changed: egui's picker goes through
/// HSV, so writing every frame would drift the stored value by float rounding.
fn color_rgb(ui: &mut egui::Ui, color: &mut [f32; 3]) {
    let mut shown = *color;
    if ui.color_edit_button_rgb(&mut shown).changed() {
        *color = shown;
    }
}

/// [`color_rgb`] with alpha.
fn color_rgba(ui: &mut egui::Ui, color: &mut [f32; 4]) {
    let mut shown = *color;
    if ui.color_edit_button_rgba_unmultiplied(&mut shown).changed() {
        *color = shown;
    }
}

/// A drag value limited to `range` when edited. A value already outside it is shown as it
/// is: merely showing a component must never change it.
fn ranged(
    value: &mut f32,
    speed: f64,
    range: std::ops::RangeInclusive<f64>,
) -> egui::DragValue<'_> {
    egui::DragValue::new(value)
        .speed(speed)
        .range(range)
        .clamp_existing_to_range(false)
}

fn vec3_row(ui: &mut egui::Ui, label: &str, v: &mut [f32; 3], speed: f32) {
    ui.horizontal(|ui| {
        ui.label(label);
        for (axis, x) in ["X", "Y", "Z"].iter().zip(v.iter_mut()) {
            ui.add(
                egui::DragValue::new(x)
                    .speed(speed)
                    .prefix(format!("{axis} ")),
            );
        }
    });
}

fn transform_ui(ui: &mut egui::Ui, t: &mut Transform) {
    let mut translation = t.translation.to_array();
    vec3_row(ui, "Position", &mut translation, 0.05);
    let (y, x, z) = t.rotation.to_euler(EulerRot::YXZ);
    // `+ 0.0` shows -0.0 as 0.0.
    let euler = [x, y, z].map(|a| a.to_degrees() + 0.0);
    let mut edited = euler;
    vec3_row(ui, "Rotation", &mut edited, 0.5);
    let mut scale = t.scale.to_array();
    vec3_row(ui, "Scale", &mut scale, 0.02);
    t.translation = Vec3::from_array(translation);
    t.scale = Vec3::from_array(scale);
    if edited != euler {
        t.rotation = Quat::from_euler(
            EulerRot::YXZ,
            edited[1].to_radians(),
            edited[0].to_radians(),
            edited[2].to_radians(),
        );
    }
}

const SHADINGS: [ShadingMode; 5] = [
    ShadingMode::Unlit,
    ShadingMode::LitLow,
    ShadingMode::Lit,
    ShadingMode::Normal,
    ShadingMode::Wireframe,
];

fn mesh_renderer_ui(ui: &mut egui::Ui, m: &mut MeshRenderer) {
    ui.horizontal(|ui| {
        ui.label("Mesh");
        let name = onyx_plugin_api::MeshId::BUILTIN
            .iter()
            .find(|(id, _)| *id == m.mesh)
            .map(|(_, n)| (*n).to_owned())
            .unwrap_or_else(|| format!("mesh {}", m.mesh.0));
        ui.weak(name);
    });
    ui.horizontal(|ui| {
        ui.label("Colour");
        color_rgba(ui, &mut m.material.color);
    });
    ui.horizontal(|ui| {
        ui.label("Shading");
        egui::ComboBox::from_id_salt("shading")
            .selected_text(format!("{:?}", m.material.shading))
            .show_ui(ui, |ui| {
                for mode in SHADINGS {
                    ui.selectable_value(&mut m.material.shading, mode, format!("{mode:?}"));
                }
            });
    });
    ui.checkbox(&mut m.visible, "Visible");
}

fn light_ui(ui: &mut egui::Ui, light: &mut Light) {
    let (kind, color, intensity) = match light {
        Light::Ambient { color, intensity } => ("Ambient", color, intensity),
        Light::Directional { color, intensity } => ("Directional", color, intensity),
        Light::Point {
            color, intensity, ..
        } => ("Point", color, intensity),
    };
    ui.label(kind);
    ui.horizontal(|ui| {
        ui.label("Colour");
        color_rgb(ui, color);
    });
    ui.horizontal(|ui| {
        ui.label("Intensity");
        ui.add(ranged(intensity, 0.05, 0.0..=1000.0));
    });
    if let Light::Point { range, .. } = light {
        ui.horizontal(|ui| {
            ui.label("Range");
            ui.add(ranged(range, 0.1, 0.0..=10_000.0));
        });
    }
}

fn camera_ui(ui: &mut egui::Ui, camera: &mut Camera) {
    let perspective = matches!(camera.projection, Projection::Perspective { .. });
    ui.horizontal(|ui| {
        if ui.radio(perspective, "Perspective").clicked() && !perspective {
            camera.projection = Projection::Perspective { fov_y: 0.8 };
        }
        if ui.radio(!perspective, "Orthographic").clicked() && perspective {
            camera.projection = Projection::Orthographic { height: 10.0 };
        }
    });
    match &mut camera.projection {
        Projection::Perspective { fov_y } => {
            ui.horizontal(|ui| {
                ui.label("Field of view");
                ui.drag_angle(fov_y);
            });
        }
        Projection::Orthographic { height } => {
            ui.horizontal(|ui| {
                ui.label("Height");
                ui.add(ranged(height, 0.1, 0.01..=10_000.0));
            });
        }
    }
    ui.horizontal(|ui| {
        ui.label("Near");
        ui.add(ranged(&mut camera.near, 0.01, 0.001..=100.0));
        ui.label("Far");
        ui.add(ranged(&mut camera.far, 1.0, 1.0..=100_000.0));
    });
    ui.checkbox(&mut camera.active, "Active");
}

fn rigid_body_ui(ui: &mut egui::Ui, body: &mut RigidBody) {
    ui.horizontal(|ui| {
        ui.label("Kind");
        egui::ComboBox::from_id_salt("body-kind")
            .selected_text(format!("{:?}", body.kind))
            .show_ui(ui, |ui| {
                for kind in [BodyKind::Dynamic, BodyKind::Kinematic, BodyKind::Static] {
                    ui.selectable_value(&mut body.kind, kind, format!("{kind:?}"));
                }
            });
    });
    ui.horizontal(|ui| {
        // 0 kg means "from the colliders' densities".
        let mut from_density = body.mass == 0.0;
        if ui
            .checkbox(&mut from_density, "Mass from density")
            .changed()
        {
            body.mass = if from_density { 0.0 } else { 1.0 };
        }
        if !from_density {
            ui.add(ranged(&mut body.mass, 0.05, 0.001..=1.0e6).suffix(" kg"));
        }
    });
    ui.horizontal(|ui| {
        ui.label("Gravity scale");
        ui.add(egui::DragValue::new(&mut body.gravity_scale).speed(0.05));
    });
    let mut velocity = body.linear_velocity.to_array();
    vec3_row(ui, "Velocity", &mut velocity, 0.05);
    body.linear_velocity = Vec3::from_array(velocity);
    ui.horizontal(|ui| {
        ui.checkbox(&mut body.ccd, "CCD");
        ui.checkbox(&mut body.can_sleep, "Can sleep");
    });
}

fn collider_ui(ui: &mut egui::Ui, collider: &mut Collider) {
    let kind = match collider.shape {
        ColliderShape::Sphere { .. } => "Sphere",
        ColliderShape::Box { .. } => "Box",
        ColliderShape::Capsule { .. } => "Capsule",
        ColliderShape::Plane => "Plane",
        ColliderShape::ConvexHull { .. } => "Convex hull",
        ColliderShape::TriMesh { .. } => "Triangle mesh",
    };
    ui.horizontal(|ui| {
        ui.label("Shape");
        egui::ComboBox::from_id_salt("collider-shape")
            .selected_text(kind)
            .show_ui(ui, |ui| {
                let choices = [
                    ("Sphere", ColliderShape::Sphere { radius: 0.5 }),
                    (
                        "Box",
                        ColliderShape::Box {
                            half_extents: [0.5; 3],
                        },
                    ),
                    (
                        "Capsule",
                        ColliderShape::Capsule {
                            half_height: 0.5,
                            radius: 0.25,
                        },
                    ),
                    ("Plane", ColliderShape::Plane),
                ];
                for (name, shape) in choices {
                    if ui.selectable_label(kind == name, name).clicked() && kind != name {
                        collider.shape = shape;
                    }
                }
            });
    });
    match &mut collider.shape {
        ColliderShape::Sphere { radius } => {
            ui.horizontal(|ui| {
                ui.label("Radius");
                ui.add(ranged(radius, 0.01, 0.001..=1.0e4));
            });
        }
        ColliderShape::Box { half_extents } => vec3_row(ui, "Half extents", half_extents, 0.01),
        ColliderShape::Capsule {
            half_height,
            radius,
        } => {
            ui.horizontal(|ui| {
                ui.label("Half height");
                ui.add(ranged(half_height, 0.01, 0.0..=1.0e4));
                ui.label("Radius");
                ui.add(ranged(radius, 0.01, 0.001..=1.0e4));
            });
        }
        _ => {}
    }
    ui.horizontal(|ui| {
        ui.label("Friction");
        ui.add(ranged(&mut collider.friction, 0.01, 0.0..=10.0));
        ui.label("Restitution");
        ui.add(ranged(&mut collider.restitution, 0.01, 0.0..=1.0));
    });
    ui.horizontal(|ui| {
        ui.label("Density");
        ui.add(ranged(&mut collider.density, 0.05, 0.001..=1.0e5));
    });
}
