//! The Create menu's entities and their components.

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::tools::ComponentValue;
use onyx_plugin_api::{
    BuiltinValue, Camera, Collider, Ctx, Light, Material, MeshId, MeshRenderer, Transform,
};

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

fn value(component: impl Into<BuiltinValue>) -> ComponentValue {
    ComponentValue::Builtin(component.into())
}
