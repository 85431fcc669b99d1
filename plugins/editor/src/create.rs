//! The Create menu's entities and their components.

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::tools::ComponentValue;
use onyx_plugin_api::{
    BuiltinValue, Camera, Collider, Ctx, Light, Material, MeshId, MeshRenderer, Transform,
};

use crate::history::Command;
use crate::state::EditorState;

/// What the Create menu makes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Primitive {
    /// A name and a transform.
    Empty,
    /// A unit cube.
    Cube,
    /// A unit sphere.
    Sphere,
    /// A plane.
    Plane,
    /// A capsule.
    Capsule,
    /// A point light.
    Light,
    /// A perspective camera.
    Camera,
}

impl Primitive {
    /// Every kind, in menu order.
    pub const ALL: [Primitive; 7] = [
        Primitive::Empty,
        Primitive::Cube,
        Primitive::Sphere,
        Primitive::Plane,
        Primitive::Capsule,
        Primitive::Light,
        Primitive::Camera,
    ];

    /// The menu entry and the new entity's name.
    pub fn label(self) -> &'static str {
        match self {
            Primitive::Empty => "Empty",
            Primitive::Cube => "Cube",
            Primitive::Sphere => "Sphere",
            Primitive::Plane => "Plane",
            Primitive::Capsule => "Capsule",
            Primitive::Light => "Light",
            Primitive::Camera => "Camera",
        }
    }

    /// The components besides the name, placed at `at`. Shapes come with a collider of
    /// their mesh's size (static until a `RigidBody` is added; the plane's is an infinite
    /// half-space, as a floor wants).
    pub fn components(self, at: Vec3) -> Vec<ComponentValue> {
        let mut out = vec![value(Transform::from_translation(at))];
        let mesh =
            |id: MeshId| value(MeshRenderer::new(id).with_material(Material::color(0.8, 0.8, 0.8)));
        match self {
            Primitive::Empty => {}
            Primitive::Cube => {
                out.push(mesh(MeshId::CUBE));
                out.push(value(Collider::cuboid(0.5, 0.5, 0.5)));
            }
            Primitive::Sphere => {
                out.push(mesh(MeshId::SPHERE));
                out.push(value(Collider::sphere(0.5)));
            }
            Primitive::Plane => {
                out.push(mesh(MeshId::PLANE));
                out.push(value(Collider::plane()));
            }
            Primitive::Capsule => {
                out.push(mesh(MeshId::CAPSULE));
                out.push(value(Collider::capsule(0.5, 0.5)));
            }
            Primitive::Light => out.push(value(Light::point(10.0))),
            Primitive::Camera => out.push(value(Camera::perspective(0.8))),
        }
        out
    }
}

/// Loads the OBJ model at `path` and creates an entity showing it, named after the file, in
/// front of the camera (undoable). A file that cannot be read shows the renderer's fallback
/// and its error in the console.
pub fn import_obj(ctx: &mut Ctx, state: &mut EditorState, path: &str) {
    let mesh = match ctx.load_mesh(path) {
        Ok(mesh) => mesh,
        Err(e) => return state.report(ctx, &format!("cannot import {path}"), e),
    };
    let name = std::path::Path::new(path)
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "Model".to_owned());
    let at = state.viewport.spawn_point();
    let components = vec![
        value(Transform::from_translation(at)),
        value(MeshRenderer::new(mesh)),
    ];
    state.create(ctx, &name, components);
}

/// Brings the glTF file at `path` in as its node tree under one new entity named after the
/// file, placed in front of the camera and selected (one undoable step). A file that cannot
/// be imported spawns nothing and shows its error in the console.
pub fn import_gltf(ctx: &mut Ctx, state: &mut EditorState, path: &str) {
    let root = match ctx.import_gltf(path) {
        Ok(root) => root,
        Err(e) => return state.report(ctx, &format!("cannot import {path}"), e),
    };
    let at = state.viewport.spawn_point();
    let placed = ctx
        .get::<Transform>(root)
        .map(|t| Transform {
            translation: at,
            ..t
        })
        .and_then(|t| ctx.set(root, t));
    if let Err(e) = placed {
        state.report(ctx, &format!("cannot place {path}"), e);
    }
    match crate::state::subtree(ctx, root).and_then(|entities| {
        entities
            .into_iter()
            .map(|entity| {
                crate::history::snapshot(ctx, entity)
                    .map(|components| Command::Create { entity, components })
            })
            .collect::<Result<Vec<_>, _>>()
    }) {
        Ok(commands) => {
            if let Some(command) = Command::group(commands) {
                state.record(ctx, command);
            }
            state.select(root);
        }
        Err(e) => state.report(ctx, &format!("cannot record the import of {path}"), e),
    }
}

fn value(component: impl Into<BuiltinValue>) -> ComponentValue {
    ComponentValue::Builtin(component.into())
}
