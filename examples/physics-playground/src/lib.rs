//! # Lesson 5: a physics playground — forces, raycast picking, contact events
//!
//! Give an entity a [`Collider`] and it is solid; add a [`RigidBody`] and the host simulates
//! it every fixed step, writing its pose back into its `Transform`. A plugin acts on bodies
//! through `ctx`:
//!
//! - **forces**: `ctx.apply_force` (newtons, for the next step: call it every step you push)
//!   and `ctx.apply_impulse` (N·s, a kick) — the arrow keys roll the ball, Space makes it
//!   jump when it stands on something (`RigidBody::grounded`);
//! - **raycast picking**: `ctx.screen_ray` turns the cursor into a ray through the camera,
//!   `ctx.raycast` finds the first collider along it — a left click shoves what it hits;
//! - **contact events**: `Event::Physics(PhysicsEvent::ContactStarted { a, b, .. })` arrives in
//!   `on_event` when two colliders start touching — they are counted, and a box the ball hits
//!   turns red.
//!
//! ```sh
//! cargo build --workspace
//! target/debug/onyx run --plugin physics_playground
//! ```
//!
//! Checked by `tests/tests/e2e/examples.rs`: the boxes come to rest on the ground (contacts
//! are reported), a click shoves the box under the cursor, the arrow keys roll the ball.

use onyx_plugin_api::glam::camera::rh::view::look_at_quat;
use onyx_plugin_api::glam::{Quat, Vec2, Vec3};
use onyx_plugin_api::{
    export_plugin, Camera, Collider, Component, Ctx, CtxError, Entity, Event, Key, Light, Material,
    MeshId, MeshRenderer, MouseButton, Name, PhysicsEvent, Plugin, RigidBody, Transform,
};

/// Where the camera looks from and at (the middle of the picture is the pyramid's second row).
const EYE: Vec3 = Vec3::new(0.0, 4.0, 10.0);
const TARGET: Vec3 = Vec3::new(0.3, 1.2, 0.0);
/// Density of the boxes and the ball, kg/m³ (light wood): a 1 m box weighs 200 kg, the
/// ball (0.5 m radius) 105 kg. Forces and impulses below are sized for these masses.
pub const DENSITY: f32 = 200.0;
/// The force the arrow keys push the ball with, newtons (about 3 m/s² on the ball).
pub const ROLL_FORCE: f32 = 400.0;
/// The kick Space gives the ball, N·s (it leaves the ground at about 4 m/s).
pub const JUMP_IMPULSE: f32 = 400.0;
/// The kick a click gives what it hits, N·s (a box starts at about 4 m/s).
pub const SHOVE_IMPULSE: f32 = 800.0;

const BOX_COLOUR: Material = Material::color(0.8, 0.7, 0.5);
const HIT_COLOUR: Material = Material::color(0.9, 0.2, 0.2);

/// What happened so far, kept on the `stats` entity (the editor's inspector shows it).
#[derive(Clone, Debug, Default, serde::Serialize, serde::Deserialize)]
pub struct PlaygroundStats {
    /// Contacts started.
    pub contacts: u32,
    /// Bodies shoved by a click.
    pub shoves: u32,
}

impl Component for PlaygroundStats {
    const NAME: &'static str = "physics_playground.stats";
}

/// The plugin.
#[derive(Default)]
pub struct PhysicsPlayground {
    ball: Option<Entity>,
    boxes: Vec<Entity>,
    stats_entity: Option<Entity>,
    stats: PlaygroundStats,
    /// The window's size in pixels (the host tells us in `on_resize`).
    window: Option<Vec2>,
}

impl PhysicsPlayground {
    fn build_scene(&mut self, ctx: &mut Ctx) -> Result<(), CtxError> {
        let look = look_at_quat(EYE, TARGET, Vec3::Y).inverse();
        let camera = ctx.spawn((
            Name::new("camera"),
            Transform::from_translation(EYE).with_rotation(look),
            Camera::perspective(50f32.to_radians()),
        ))?;
        ctx.set_camera(camera)?;
        ctx.spawn((
            Name::new("sun"),
            Transform::IDENTITY.with_rotation(Quat::from_rotation_x(-0.9)),
            Light::sun(),
        ))?;
        // A collider without a body is static: the ground never moves.
        ctx.spawn((
            Name::new("ground"),
            Transform::IDENTITY.with_scale(Vec3::new(20.0, 1.0, 20.0)),
            MeshRenderer::new(MeshId::PLANE).with_material(Material::color(0.4, 0.5, 0.4)),
            Collider::plane(),
        ))?;
        // A pyramid of boxes: rows of 3, 2 and 1, each box 1 m.
        for (row, count) in [3, 2, 1].into_iter().enumerate() {
            for i in 0..count {
                let x = i as f32 - (count - 1) as f32 / 2.0;
                let y = 0.5 + row as f32;
                let cube = ctx.spawn((
                    Name::new(format!("box {row}.{i}")),
                    Transform::from_xyz(x, y, 0.0),
                    MeshRenderer::new(MeshId::CUBE).with_material(BOX_COLOUR),
                    RigidBody::dynamic(),
                    Collider::cuboid(0.5, 0.5, 0.5)
                        .with_friction(0.6)
                        .with_density(DENSITY),
                ))?;
                self.boxes.push(cube);
            }
        }
        let ball = ctx.spawn((
            Name::new("ball"),
            Transform::from_xyz(-3.0, 0.5, 2.0),
            MeshRenderer::new(MeshId::SPHERE).with_material(Material::color(0.2, 0.4, 0.9)),
            RigidBody::dynamic().with_ccd(true),
            Collider::sphere(0.5)
                .with_restitution(0.3)
                .with_density(DENSITY),
        ))?;
        self.ball = Some(ball);
        self.stats_entity = Some(ctx.spawn((Name::new("stats"), PlaygroundStats::default()))?);
        Ok(())
    }

    /// Shoves whatever is under the cursor (left click).
    fn shove_under_cursor(&mut self, ctx: &mut Ctx) {
        let cursor = ctx.input().cursor();
        let size = self.window.unwrap_or(Vec2::new(1280.0, 720.0));
        let Some(ray) = ctx.screen_ray(cursor, size) else {
            return;
        };
        let Some(hit) = ctx.raycast(ray.origin, ray.direction, 100.0) else {
            return;
        };
        // Static colliders (the ground) have no body to push: the call says so.
        if ctx
            .apply_impulse(hit.entity, ray.direction * SHOVE_IMPULSE)
            .is_ok()
        {
            self.stats.shoves += 1;
            ctx.info(format!("shoved {:?} at {:.2}", hit.entity, hit.point));
        }
    }
}

impl Plugin for PhysicsPlayground {
    fn on_init(&mut self, ctx: &mut Ctx) {
        if let Err(error) = self.build_scene(ctx) {
            ctx.error(format!("could not build the scene: {error}"));
        }
    }

    fn on_resize(&mut self, _ctx: &mut Ctx, width: u32, height: u32) {
        self.window = Some(Vec2::new(width as f32, height as f32));
    }

    fn on_event(&mut self, ctx: &mut Ctx, event: &Event) {
        let Event::Physics(PhysicsEvent::ContactStarted { a, b, .. }) = event else {
            return;
        };
        self.stats.contacts += 1;
        // The ball hit a box: paint the box.
        let other = match self.ball {
            Some(ball) if *a == ball => *b,
            Some(ball) if *b == ball => *a,
            _ => return,
        };
        if self.boxes.contains(&other) {
            let red = MeshRenderer::new(MeshId::CUBE).with_material(HIT_COLOUR);
            ctx.set(other, red).ok();
        }
    }

    fn on_fixed_update(&mut self, ctx: &mut Ctx) {
        let Some(ball) = self.ball else { return };
        let input = ctx.input();
        let mut push = Vec3::ZERO;
        for (key, along) in [
            (Key::ArrowLeft, Vec3::NEG_X),
            (Key::ArrowRight, Vec3::X),
            (Key::ArrowUp, Vec3::NEG_Z),
            (Key::ArrowDown, Vec3::Z),
        ] {
            if input.key_down(key) {
                push += along;
            }
        }
        // A force lasts one step: push in every step the key is held.
        if push != Vec3::ZERO {
            ctx.apply_force(ball, push.normalize() * ROLL_FORCE).ok();
        }
    }

    fn on_update(&mut self, ctx: &mut Ctx, _dt: f32) -> onyx_plugin_api::Flow {
        let input = ctx.input();
        // Presses are edges of this frame: read them here, not in fixed steps (a frame may
        // run none).
        if input.mouse_pressed(MouseButton::Left) {
            self.shove_under_cursor(ctx);
        }
        if let Some(ball) = self.ball {
            let grounded = ctx.get::<RigidBody>(ball).is_ok_and(|body| body.grounded);
            if input.key_pressed(Key::Space) && grounded {
                ctx.apply_impulse(ball, Vec3::Y * JUMP_IMPULSE).ok();
            }
        }
        if let Some(stats) = self.stats_entity {
            ctx.set(stats, self.stats.clone()).ok();
        }
        onyx_plugin_api::Flow::Continue
    }
}

export_plugin!(PhysicsPlayground);
