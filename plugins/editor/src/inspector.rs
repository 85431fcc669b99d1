//! The Inspector panel: the selection's name and every component, with fitting widgets for
//! the built-ins (a JSON tree for a built-in without one, and for plugin components); add
//! and remove components. Built-ins are read and written typed; plugin components as JSON
//! values.

use base64::Engine as _;
use onyx_plugin_api::glam::{EulerRot, Quat, Vec3};
use onyx_plugin_api::tools::{ComponentKey, ComponentValue, PluginValue};
use onyx_plugin_api::{
    egui, AlphaMode, BodyKind, BuiltinId, BuiltinValue, Camera, Collider, ColliderShape, Component,
    Ctx, Entity, Light, Material, MeshRenderer, Parent, Projection, RigidBody, Script, ShadingMode,
    Transform,
};

use crate::history::Command;
use crate::state::EditorState;

/// The inspector's own state.
#[derive(Debug, Default)]
pub struct InspectorState {
    /// The name being typed, for which entity.
    name: Option<(Entity, String)>,
}

/// One change the user made: which component, its value before (`None`: being added) and
/// after (`None`: removed).
struct Edit {
    key: ComponentKey,
    old: Option<ComponentValue>,
    new: Option<ComponentValue>,
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

    let mut edits: Vec<Edit> = Vec::new();
    egui::ScrollArea::vertical()
        .auto_shrink([false, false])
        .show(ui, |ui| {
            for value in &components {
                if matches!(value, ComponentValue::Builtin(BuiltinValue::Name(_))) {
                    continue;
                }
                let name = value.name();
                let id = egui::Id::new(("inspector", entity, name));
                let mut remove = false;
                let mut new = None;
                egui::CollapsingHeader::new(name)
                    .id_salt(id)
                    .default_open(true)
                    .show(ui, |ui| {
                        new = component_ui(ui, ctx, state, entity, value, id);
                        if ui.small_button(format!("Remove {name}")).clicked() {
                            remove = true;
                        }
                    });
                if remove || new.is_some() {
                    edits.push(Edit {
                        key: value.key(),
                        old: Some(value.clone()),
                        new: if remove { None } else { new },
                    });
                }
            }
            ui.separator();
            ui.menu_button("Add Component", |ui| {
                let present = |key: &ComponentKey| components.iter().any(|c| c.key() == *key);
                for &id in BuiltinId::ALL {
                    let key = ComponentKey::Builtin(id);
                    let Some(default) = id.tool_default() else {
                        continue; // no sensible default: set it another way (a parent by dragging)
                    };
                    if id == BuiltinId::Name {
                        continue;
                    }
                    if ui
                        .add_enabled(!present(&key), egui::Button::new(id.name()))
                        .clicked()
                    {
                        edits.push(Edit {
                            key,
                            old: None,
                            new: Some(ComponentValue::Builtin(default)),
                        });
                    }
                }
                let script = ComponentKey::Plugin(Script::NAME.to_owned());
                if ui
                    .add_enabled(!present(&script), egui::Button::new(Script::NAME))
                    .clicked()
                {
                    edits.push(Edit {
                        key: script,
                        old: None,
                        new: new_script(ctx),
                    });
                }
            });
        });

    for Edit { key, old, new } in edits {
        let result = match &new {
            Some(value) => ctx.set_component(entity, value.clone()),
            None => ctx.remove_component(entity, &key),
        };
        match result {
            Ok(()) => {
                let set = old.is_some() && new.is_some();
                let command = Command::SetComponent {
                    entity,
                    key,
                    old,
                    new,
                };
                if set {
                    state.record_merged(ctx, command);
                } else {
                    state.record(ctx, command);
                }
            }
            Err(e) => state.report(ctx, &format!("cannot edit {}", key.name()), e),
        }
    }
}

/// A new `Script` component: the first registered behaviour with its default parameters.
fn new_script(ctx: &mut Ctx) -> Option<ComponentValue> {
    let script = ctx
        .registered_scripts()
        .ok()
        .and_then(|all| all.into_iter().next())
        .map(|s| Script {
            name: s.name,
            params: s.default_params,
        })
        .unwrap_or_default();
    Some(ComponentValue::Plugin {
        name: Script::NAME.to_owned(),
        value: PluginValue::Json(serde_json::to_value(script).ok()?),
    })
}

fn name_field(
    ui: &mut egui::Ui,
    ctx: &mut Ctx,
    state: &mut EditorState,
    entity: Entity,
    components: &[ComponentValue],
) {
    let current: String = components
        .iter()
        .find_map(|c| match c {
            ComponentValue::Builtin(BuiltinValue::Name(name)) => Some(name.0.clone()),
            _ => None,
        })
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

/// Edits `value` in place with `edit`; the new value when the user changed it.
fn edited<T: Clone + PartialEq>(value: &T, edit: impl FnOnce(&mut T)) -> Option<T> {
    let mut copy = value.clone();
    edit(&mut copy);
    (copy != *value).then_some(copy)
}

/// The widgets of one component; the new value when the user changed it.
fn component_ui(
    ui: &mut egui::Ui,
    ctx: &mut Ctx,
    state: &EditorState,
    entity: Entity,
    value: &ComponentValue,
    id: egui::Id,
) -> Option<ComponentValue> {
    let builtin = |v: BuiltinValue| Some(ComponentValue::Builtin(v));
    match value {
        ComponentValue::Builtin(b) => match b {
            BuiltinValue::Transform(t) => {
                let new = edited(t, |t| transform_ui(ui, t));
                world_position_ui(ui, ctx, entity);
                builtin(new?.into())
            }
            BuiltinValue::Parent(Parent(parent)) => {
                parent_ui(ui, state, *parent);
                None
            }
            BuiltinValue::MeshRenderer(m) => {
                builtin(edited(m, |m| mesh_renderer_ui(ui, m))?.into())
            }
            BuiltinValue::Light(l) => builtin(edited(l, |l| light_ui(ui, l))?.into()),
            BuiltinValue::Camera(c) => builtin(edited(c, |c| camera_ui(ui, c))?.into()),
            BuiltinValue::RigidBody(r) => builtin(edited(r, |r| rigid_body_ui(ui, r))?.into()),
            BuiltinValue::Collider(c) => builtin(edited(c, |c| collider_ui(ui, c))?.into()),
            other => {
                // A built-in without a widget of its own: its fields as a JSON tree.
                let mut json = other.to_json();
                if !crate::json_tree::edit(ui, "", &mut json, id) {
                    return None;
                }
                match other.id().value_from_json(json) {
                    Ok(value) => builtin(value),
                    Err(e) => {
                        ui.colored_label(egui::Color32::LIGHT_RED, e);
                        None
                    }
                }
            }
        },
        ComponentValue::Plugin {
            name,
            value: PluginValue::Json(json),
        } => {
            let mut json = json.clone();
            let changed = if name == Script::NAME {
                script_ui(ui, ctx, &mut json, id)
            } else {
                crate::json_tree::edit(ui, "", &mut json, id)
            };
            changed.then(|| ComponentValue::Plugin {
                name: name.clone(),
                value: PluginValue::Json(json),
            })
        }
        ComponentValue::Plugin {
            name,
            value: PluginValue::Raw(bytes),
        } => {
            let engine = base64::engine::general_purpose::STANDARD;
            let mut text = engine.encode(bytes);
            let changed = ui
                .horizontal(|ui| {
                    ui.label(format!("{} bytes, base64", bytes.len()));
                    ui.text_edit_singleline(&mut text).changed()
                })
                .inner;
            let decoded = engine.decode(text.trim()).ok().filter(|_| changed)?;
            Some(ComponentValue::Plugin {
                name: name.clone(),
                value: PluginValue::Raw(decoded),
            })
        }
    }
}

/// The `Script` component: which registered behaviour, and its parameters.
fn script_ui(ui: &mut egui::Ui, ctx: &mut Ctx, json: &mut serde_json::Value, id: egui::Id) -> bool {
    let Ok(mut script) = serde_json::from_value::<Script>(json.clone()) else {
        ui.colored_label(egui::Color32::LIGHT_RED, "not a Script");
        return crate::json_tree::edit(ui, "", json, id);
    };
    let scripts = ctx.registered_scripts().unwrap_or_default();
    let before = script.clone();
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
    if script == before {
        return false;
    }
    match serde_json::to_value(&script) {
        Ok(value) => {
            *json = value;
            true
        }
        Err(_) => false,
    }
}

/// The entity's world position, read-only (the Transform above is local to its parent).
fn world_position_ui(ui: &mut egui::Ui, ctx: &mut Ctx, entity: Entity) {
    let Ok(pose) = ctx.world_pose(entity) else {
        return;
    };
    let p = pose.translation();
    ui.horizontal(|ui| {
        ui.label("World position");
        ui.weak(format!("X {:.3}  Y {:.3}  Z {:.3}", p.x, p.y, p.z));
    });
}

/// The parent, by name (change it by dragging in the hierarchy).
fn parent_ui(ui: &mut egui::Ui, state: &EditorState, parent: Entity) {
    let row = state.entities.entities().iter().position(|e| *e == parent);
    let label = row.map_or_else(
        || format!("entity {parent}"),
        |r| state.row_label(r).into_owned(),
    );
    ui.horizontal(|ui| {
        ui.label("Parent");
        ui.strong(label);
    });
    ui.weak("drag it in the Hierarchy to change it");
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
    material_ui(ui, &mut m.material);
    ui.checkbox(&mut m.visible, "Visible");
}

const ALPHA_MODES: [AlphaMode; 3] = [AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend];

/// The physically based part of a material: metallic, roughness, emission, alpha, sides.
fn material_ui(ui: &mut egui::Ui, m: &mut Material) {
    ui.horizontal(|ui| {
        ui.label("Metallic");
        ui.add(ranged(&mut m.metallic, 0.01, 0.0..=1.0));
        ui.label("Roughness");
        ui.add(ranged(&mut m.roughness, 0.01, 0.0..=1.0));
    });
    ui.horizontal(|ui| {
        ui.label("Emissive");
        color_rgb(ui, &mut m.emissive);
    });
    ui.horizontal(|ui| {
        ui.label("Alpha");
        egui::ComboBox::from_id_salt("alpha-mode")
            .selected_text(format!("{:?}", m.alpha_mode))
            .show_ui(ui, |ui| {
                for mode in ALPHA_MODES {
                    ui.selectable_value(&mut m.alpha_mode, mode, format!("{mode:?}"));
                }
            });
        if m.alpha_mode == AlphaMode::Mask {
            ui.label("Cutoff");
            ui.add(ranged(&mut m.alpha_cutoff, 0.01, 0.0..=1.0));
        }
    });
    ui.checkbox(&mut m.double_sided, "Double-sided");
}

fn light_ui(ui: &mut egui::Ui, light: &mut Light) {
    let (kind, color, intensity) = match light {
        Light::Ambient { color, intensity } => ("Ambient", color, intensity),
        Light::Directional {
            color, intensity, ..
        } => ("Directional", color, intensity),
        Light::Point {
            color, intensity, ..
        } => ("Point", color, intensity),
        Light::Spot {
            color, intensity, ..
        } => ("Spot", color, intensity),
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
    if let Light::Point { range, .. } | Light::Spot { range, .. } = light {
        ui.horizontal(|ui| {
            ui.label("Range");
            ui.add(ranged(range, 0.1, 0.0..=10_000.0));
        });
    }
    if let Light::Spot {
        inner_angle,
        outer_angle,
        ..
    } = light
    {
        ui.horizontal(|ui| {
            ui.label("Cone");
            ui.add(
                egui::DragValue::from_get_set(|set| {
                    if let Some(degrees) = set {
                        *inner_angle = (degrees as f32).to_radians();
                    }
                    f64::from(inner_angle.to_degrees())
                })
                .speed(0.5)
                .range(0.0..=89.0)
                .suffix("°"),
            );
            ui.add(
                egui::DragValue::from_get_set(|set| {
                    if let Some(degrees) = set {
                        *outer_angle = (degrees as f32).to_radians();
                    }
                    f64::from(outer_angle.to_degrees())
                })
                .speed(0.5)
                .range(0.0..=89.0)
                .suffix("°"),
            );
        });
    }
    if let Light::Directional { shadows, .. }
    | Light::Point { shadows, .. }
    | Light::Spot { shadows, .. } = light
    {
        ui.checkbox(shadows, "Shadows");
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
