//! # Lesson 1: a first plugin
//!
//! A plugin is a `cdylib` crate that implements [`Plugin`] and exports it with
//! [`export_plugin!`]. The host loads the library, calls `on_init` once every plugin is
//! attached, then each frame `on_fixed_update` (60 times a second) and `on_update`.
//!
//! This one builds a tiny scene in `on_init` — a camera, a sun, an ambient light and an orange
//! cube — and turns the cube a little every fixed step. Everything it spawns lives in the
//! host's world; the plugin keeps only the cube's [`Entity`] handle.
//!
//! Run it from the repository root:
//!
//! ```sh
//! cargo build --workspace
//! target/debug/onyx run --plugin first_plugin
//! ```
//!
//! Things to try: change [`TURN_SPEED`], give the cube a [`ShadingMode::Wireframe`]
//! material, or spawn a second cube at `Transform::from_xyz(2.0, 0.5, 0.0)`.
//!
//! Checked by `tests/tests/e2e/examples.rs`: the cube is drawn in the middle of the picture
//! and it turns.
//!
//! [`ShadingMode::Wireframe`]: onyx_plugin_api::ShadingMode::Wireframe

use onyx_plugin_api::glam::camera::rh::view::look_at_quat;
use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::{
    export_plugin, Camera, Ctx, CtxError, Entity, Light, Material, MeshId, MeshRenderer, Name,
    Plugin, Transform,
};

/// How fast the cube turns about Y, radians per second.
pub const TURN_SPEED: f32 = 1.0;

/// The plugin: the cube it turns.
#[derive(Default)]
pub struct FirstPlugin {
    cube: Option<Entity>,
}

/// The rotation that points an entity's -Z (where cameras and suns look) from `eye` at
/// `target`, Y up.
fn looking_at(eye: Vec3, target: Vec3) -> Quat {
    look_at_quat(eye, target, Vec3::Y).inverse()
}

impl FirstPlugin {
    fn build_scene(&mut self, ctx: &mut Ctx) -> Result<(), CtxError> {
        let eye = Vec3::new(0.0, 2.0, 4.0);
        let camera = ctx.spawn((
            Name::new("camera"),
            Transform::from_translation(eye).with_rotation(looking_at(eye, Vec3::ZERO)),
            Camera::perspective(50f32.to_radians()),
        ))?;
        // Without this the host looks through the first active camera, or its own.
        ctx.set_camera(camera)?;

        let sun_from = Vec3::new(-2.0, 4.0, 3.0);
        ctx.spawn((
            Name::new("sun"),
            Transform::IDENTITY.with_rotation(looking_at(sun_from, Vec3::ZERO)),
            Light::sun(),
        ))?;
        ctx.spawn((
            Name::new("ambient"),
            Transform::IDENTITY,
            Light::Ambient {
                color: [0.6, 0.7, 1.0],
                intensity: 0.2,
            },
        ))?;

        let orange = Material::color(1.0, 0.45, 0.1);
        let cube = ctx.spawn((
            Name::new("cube"),
            Transform::IDENTITY,
            MeshRenderer::new(MeshId::CUBE).with_material(orange),
        ))?;
        self.cube = Some(cube);
        Ok(())
    }
}

impl Plugin for FirstPlugin {
    fn on_init(&mut self, ctx: &mut Ctx) {
        if let Err(error) = self.build_scene(ctx) {
            ctx.error(format!("could not build the scene: {error}"));
        }
    }

    fn on_fixed_update(&mut self, ctx: &mut Ctx) {
        let Some(cube) = self.cube else { return };
        // Fixed steps have a fixed length: the same motion at any frame rate.
        let turn = Quat::from_rotation_y(TURN_SPEED * ctx.time().fixed_delta);
        if let Ok(mut transform) = ctx.get::<Transform>(cube) {
            transform.rotation = (turn * transform.rotation).normalize();
            ctx.set(cube, transform).ok();
        }
    }
}

export_plugin!(FirstPlugin);
