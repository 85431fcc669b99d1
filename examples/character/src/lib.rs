//! Example: a kinematic character walked with the keyboard.
//!
//! A capsule (`RigidBody::kinematic()` + `Collider::capsule`) moved each fixed step by
//! [`Ctx::move_character`]: it slides along walls, walks up the gentle ramp and not the steep
//! one, climbs the stairs (each step lower than [`CharacterController::step_height`]), stays
//! on the ground going down, and pushes the crates. The camera follows it.
//!
//! - W / S or the up / down arrows walk forward (−Z) and back, A / D or left / right
//!   sideways; Space jumps while on the ground.
//!
//! The plugin keeps the character's vertical speed itself: gravity is added to it every step
//! and it is zeroed when a move ends on the ground. The horizontal part of the move is the
//! keys' direction times [`WALK_SPEED`].
//!
//! ```sh
//! cargo build --workspace
//! target/debug/onyx run --plugin character
//! ```
//!
//! Checked by `tests/tests/e2e/examples.rs`: holding W walks the capsule up the stairs onto
//! the landing, Space lifts it off the ground.

use onyx_plugin_api::glam::camera::rh::view::look_at_quat;
use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::{
    export_plugin, Camera, CharacterController, Collider, Ctx, CtxError, Entity, Key, Light,
    Material, MeshId, MeshRenderer, Name, Plugin, RigidBody, Transform,
};

/// Walking speed, m/s.
pub const WALK_SPEED: f32 = 3.0;
/// Upward speed of a jump, m/s (about 0.6 m high).
pub const JUMP_SPEED: f32 = 3.5;
/// Gravity, m/s².
pub const GRAVITY: f32 = 9.81;
/// Stairs: steps, and each one's rise and depth, metres.
pub const STEPS: usize = 5;
/// Rise of one step, m (under the controller's 0.3 m step height).
pub const STEP_RISE: f32 = 0.2;
/// Depth of one step, m.
pub const STEP_DEPTH: f32 = 0.5;
/// Where the stairs start, metres along −Z.
pub const STAIRS_START: f32 = 3.0;
/// The capsule: half the length of its straight part and its radius, m.
pub const CAPSULE: (f32, f32) = (0.5, 0.3);
/// Where the camera sits relative to the character.
const CAMERA_OFFSET: Vec3 = Vec3::new(0.0, 3.0, 7.0);

/// The plugin: the character, the camera, and the character's vertical speed.
#[derive(Default)]
pub struct Character {
    character: Option<Entity>,
    camera: Option<Entity>,
    vertical_speed: f32,
    grounded: bool,
}

/// A fixed, drawn box of half extents `half` at `at` (a unit cube scaled to size: the
/// collider scales with the entity like the mesh).
fn block(
    ctx: &mut Ctx,
    name: &str,
    at: Vec3,
    half: Vec3,
    rotation: Quat,
    colour: Material,
) -> Result<Entity, CtxError> {
    ctx.spawn((
        Name::new(name),
        Transform::from_translation(at)
            .with_rotation(rotation)
            .with_scale(half * 2.0),
        MeshRenderer::new(MeshId::CUBE).with_material(colour),
        RigidBody::fixed(),
        Collider::cuboid(0.5, 0.5, 0.5),
    ))
}

/// A ramp rising along −X from `foot` at `angle` (radians), 2 m wide.
fn ramp(ctx: &mut Ctx, name: &str, foot: Vec3, angle: f32) -> Result<Entity, CtxError> {
    let along = Vec3::new(-angle.cos(), angle.sin(), 0.0);
    let normal = Vec3::new(angle.sin(), angle.cos(), 0.0);
    let half = Vec3::new(2.5, 0.25, 1.0);
    block(
        ctx,
        name,
        foot + along * half.x - normal * half.y,
        half,
        Quat::from_rotation_z(-angle),
        Material::color(0.5, 0.45, 0.4),
    )
}

impl Character {
    fn build_scene(&mut self, ctx: &mut Ctx) -> Result<(), CtxError> {
        ctx.spawn((
            Name::new("sun"),
            Transform::IDENTITY.with_rotation(Quat::from_rotation_x(-0.9)),
            Light::sun(),
        ))?;
        ctx.spawn((
            Name::new("ground"),
            Transform::IDENTITY.with_scale(Vec3::new(30.0, 1.0, 30.0)),
            MeshRenderer::new(MeshId::PLANE).with_material(Material::color(0.4, 0.5, 0.4)),
            Collider::plane(),
        ))?;
        // The stairs along −Z, each step a block from the ground up, then a landing.
        let stone = Material::color(0.6, 0.6, 0.65);
        for k in 0..STEPS {
            let top = STEP_RISE * (k + 1) as f32;
            let z = -(STAIRS_START + STEP_DEPTH * (k as f32 + 0.5));
            block(
                ctx,
                &format!("step {k}"),
                Vec3::new(0.0, top / 2.0, z),
                Vec3::new(1.0, top / 2.0, STEP_DEPTH / 2.0),
                Quat::IDENTITY,
                stone,
            )?;
        }
        let height = STEP_RISE * STEPS as f32;
        let landing_start = STAIRS_START + STEP_DEPTH * STEPS as f32;
        block(
            ctx,
            "landing",
            Vec3::new(0.0, height / 2.0, -(landing_start + 2.0)),
            Vec3::new(1.0, height / 2.0, 2.0),
            Quat::IDENTITY,
            stone,
        )?;
        // A ramp it walks up (20°) and one too steep for it (55°), to the left.
        ramp(
            ctx,
            "gentle ramp",
            Vec3::new(-3.0, 0.0, -2.0),
            20f32.to_radians(),
        )?;
        ramp(
            ctx,
            "steep ramp",
            Vec3::new(-3.0, 0.0, 2.0),
            55f32.to_radians(),
        )?;
        // Crates to push, to the right.
        for k in 0..3 {
            ctx.spawn((
                Name::new(format!("crate {k}")),
                Transform::from_xyz(3.0, 0.25, -1.0 - k as f32).with_scale(Vec3::splat(0.5)),
                MeshRenderer::new(MeshId::CUBE).with_material(Material::color(0.7, 0.5, 0.2)),
                RigidBody::dynamic(),
                Collider::cuboid(0.5, 0.5, 0.5).with_density(200.0),
            ))?;
        }
        let (half_height, radius) = CAPSULE;
        let start = Vec3::new(0.0, half_height + radius + 0.01, 0.0);
        let character = ctx.spawn((
            Name::new("character"),
            Transform::from_translation(start),
            MeshRenderer::new(MeshId::CAPSULE).with_material(Material::color(0.2, 0.4, 0.9)),
            RigidBody::kinematic(),
            Collider::capsule(half_height, radius),
        ))?;
        self.character = Some(character);
        let camera = ctx.spawn((
            Name::new("camera"),
            Self::camera_pose(start),
            Camera::perspective(60f32.to_radians()),
        ))?;
        ctx.set_camera(camera)?;
        self.camera = Some(camera);
        Ok(())
    }

    /// The camera behind and above `target`, looking at it.
    fn camera_pose(target: Vec3) -> Transform {
        let eye = target + CAMERA_OFFSET;
        Transform::from_translation(eye).with_rotation(look_at_quat(eye, target, Vec3::Y).inverse())
    }

    /// The walk the keys ask for, unit length or zero (forward is −Z).
    fn walk_direction(ctx: &Ctx) -> Vec3 {
        let input = ctx.input();
        let mut direction = Vec3::ZERO;
        for (keys, along) in [
            ([Key::W, Key::ArrowUp], Vec3::NEG_Z),
            ([Key::S, Key::ArrowDown], Vec3::Z),
            ([Key::A, Key::ArrowLeft], Vec3::NEG_X),
            ([Key::D, Key::ArrowRight], Vec3::X),
        ] {
            if keys.iter().any(|k| input.key_down(*k)) {
                direction += along;
            }
        }
        direction.normalize_or_zero()
    }

    fn step(&mut self, ctx: &mut Ctx) -> Result<(), CtxError> {
        let (Some(character), Some(camera)) = (self.character, self.camera) else {
            return Ok(());
        };
        let dt = ctx.time().fixed_delta;
        if self.grounded && ctx.input().key_down(Key::Space) {
            self.vertical_speed = JUMP_SPEED;
        }
        self.vertical_speed -= GRAVITY * dt;
        let desired =
            Self::walk_direction(ctx) * WALK_SPEED * dt + Vec3::Y * self.vertical_speed * dt;
        let moved = ctx.move_character(character, desired, &CharacterController::default())?;
        self.grounded = moved.grounded;
        if moved.grounded && self.vertical_speed < 0.0 {
            self.vertical_speed = 0.0;
        }
        // Something above stopped a jump.
        if desired.y > 0.0 && moved.translation.y < desired.y * 0.5 {
            self.vertical_speed = self.vertical_speed.min(0.0);
        }
        let at = ctx.world_pose(character)?.translation();
        ctx.set(camera, Self::camera_pose(at))
    }
}

impl Plugin for Character {
    fn on_init(&mut self, ctx: &mut Ctx) {
        if let Err(error) = self.build_scene(ctx) {
            ctx.error(format!("could not build the scene: {error}"));
        }
    }

    fn on_fixed_update(&mut self, ctx: &mut Ctx) {
        // Bodies are made at the first fixed step: until then there is nothing to move.
        if ctx.time().ticks == 0 {
            return;
        }
        if let Err(error) = self.step(ctx) {
            ctx.warn(format!("character: {error}"));
        }
    }
}

export_plugin!(Character);
