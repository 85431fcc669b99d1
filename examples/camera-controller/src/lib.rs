//! # Lesson 2: input and a camera controller
//!
//! `ctx.input()` is the keyboard and mouse of this frame: which keys are held
//! ([`InputState::key_down`]), which went down this frame ([`InputState::key_pressed`]),
//! the mouse buttons, how far the cursor moved and the wheel. This plugin turns them into a
//! fly camera over a field of pillars:
//!
//! - W / A / S / D move, E / Q rise and sink, Shift goes three times as fast;
//! - hold the right mouse button and move the mouse to look around;
//! - the wheel changes the speed; Escape quits.
//!
//! Motion is applied in `on_update` with the frame's `dt`, so it feels the same at any frame
//! rate (input is read once per frame; fixed steps are for simulation).
//!
//! ```sh
//! cargo build --workspace
//! target/debug/onyx run --plugin camera_controller
//! ```
//!
//! Checked by `tests/tests/e2e/examples.rs`: holding W moves the camera forward, a right
//! drag turns it, Escape quits.
//!
//! [`InputState::key_down`]: onyx_plugin_api::InputState::key_down
//! [`InputState::key_pressed`]: onyx_plugin_api::InputState::key_pressed

use onyx_plugin_api::glam::{EulerRot, Quat, Vec3};
use onyx_plugin_api::{
    export_plugin, Camera, Ctx, CtxError, Entity, Flow, Key, Light, Material, MeshId, MeshRenderer,
    MouseButton, Name, Plugin, Transform,
};

/// Starting speed, metres per second.
pub const SPEED: f32 = 4.0;
/// Radians the view turns per pixel of mouse motion.
pub const LOOK_SENSITIVITY: f32 = 0.004;

/// The plugin: the camera entity and where it looks.
#[derive(Default)]
pub struct CameraController {
    camera: Option<Entity>,
    /// Turn about Y, radians.
    yaw: f32,
    /// Tilt, radians (negative looks down).
    pitch: f32,
    /// Metres per second (the wheel changes it).
    speed: f32,
}

impl CameraController {
    fn rotation(&self) -> Quat {
        Quat::from_euler(EulerRot::YXZ, self.yaw, self.pitch, 0.0)
    }

    fn build_scene(&mut self, ctx: &mut Ctx) -> Result<(), CtxError> {
        self.speed = SPEED;
        self.pitch = -0.3;
        let camera = ctx.spawn((
            Name::new("camera"),
            Transform::from_xyz(0.0, 2.0, 8.0).with_rotation(self.rotation()),
            Camera::perspective(60f32.to_radians()),
        ))?;
        ctx.set_camera(camera)?;
        self.camera = Some(camera);
        ctx.spawn((
            Name::new("sun"),
            Transform::IDENTITY.with_rotation(Quat::from_euler(EulerRot::YXZ, 0.6, -0.9, 0.0)),
            Light::sun(),
        ))?;
        // A field of pillars to fly between.
        for x in -3..=3 {
            for z in -3..=3 {
                let height = 0.5 + ((x * x + z * z) % 4) as f32 * 0.5;
                let shade = 0.4 + 0.08 * (x + 3) as f32;
                ctx.spawn((
                    Name::new(format!("pillar {x},{z}")),
                    Transform::from_xyz(x as f32 * 3.0, height / 2.0, z as f32 * 3.0)
                        .with_scale(Vec3::new(0.6, height, 0.6)),
                    MeshRenderer::new(MeshId::CUBE).with_material(Material::color(
                        shade,
                        0.6,
                        1.0 - shade,
                    )),
                ))?;
            }
        }
        Ok(())
    }
}

impl Plugin for CameraController {
    fn on_init(&mut self, ctx: &mut Ctx) {
        if let Err(error) = self.build_scene(ctx) {
            ctx.error(format!("could not build the scene: {error}"));
        }
    }

    fn on_update(&mut self, ctx: &mut Ctx, dt: f32) -> Flow {
        let input = ctx.input();
        if input.key_pressed(Key::Escape) {
            return Flow::Quit;
        }
        let Some(camera) = self.camera else {
            return Flow::Continue;
        };
        if input.mouse_down(MouseButton::Right) {
            let moved = input.cursor_delta();
            self.yaw -= moved.x * LOOK_SENSITIVITY;
            self.pitch = (self.pitch - moved.y * LOOK_SENSITIVITY).clamp(-1.5, 1.5);
        }
        // Each wheel notch: 20 % faster or slower.
        let notches = input.scroll().y;
        if notches != 0.0 {
            self.speed = (self.speed * 1.2f32.powf(notches)).clamp(0.5, 50.0);
        }
        let mut direction = Vec3::ZERO;
        for (key, along) in [
            (Key::W, Vec3::NEG_Z),
            (Key::S, Vec3::Z),
            (Key::A, Vec3::NEG_X),
            (Key::D, Vec3::X),
            (Key::E, Vec3::Y),
            (Key::Q, Vec3::NEG_Y),
        ] {
            if input.key_down(key) {
                direction += along;
            }
        }
        let boost = if input.key_down(Key::ShiftLeft) {
            3.0
        } else {
            1.0
        };
        let Ok(mut transform) = ctx.get::<Transform>(camera) else {
            return Flow::Continue; // someone despawned it
        };
        transform.rotation = self.rotation();
        transform.translation +=
            transform.rotation * direction.normalize_or_zero() * self.speed * boost * dt;
        ctx.set(camera, transform).ok();
        Flow::Continue
    }
}

export_plugin!(CameraController);
