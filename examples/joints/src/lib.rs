//! Example: joints and a trigger zone.
//!
//! - a **door** hinged to a post (`Joint::revolute` with limits and a position motor that
//!   swings it open to 90°);
//! - a **chain** of ten links hung from the world by ball joints;
//! - a **ragdoll**: a torso with a head, two arms and two legs on ball joints with cone
//!   limits, dropped on the ground;
//! - a **trigger zone**: a sensor box that counts what enters and leaves it
//!   (`PhysicsEvent::SensorEntered` / `SensorExited`) while a ball falls through.
//!
//! ```sh
//! cargo build --workspace
//! target/debug/onyx run --plugin joints
//! ```
//!
//! Checked by `tests/tests/e2e/examples.rs`: the door opens to its motor's angle, the chain
//! hangs straight at its length, the ragdoll's limbs stay attached where it lands, and the
//! zone counts the ball once in and once out.

use onyx_plugin_api::glam::camera::rh::view::look_at_quat;
use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::{
    export_plugin, Camera, Collider, Component, Ctx, CtxError, Entity, Event, Joint, JointKind,
    JointMotor, JointTarget, Light, Material, MeshId, MeshRenderer, Name, PhysicsEvent, Plugin,
    RigidBody, Transform,
};

/// The angle the door's motor opens it to, radians.
pub const DOOR_TARGET: f32 = std::f32::consts::FRAC_PI_2;
/// Links in the chain, and the length of each, metres.
pub const LINKS: usize = 10;
/// Length of one link, m.
pub const LINK_LENGTH: f32 = 0.3;
/// Where the chain hangs from.
pub const CHAIN_ANCHOR: Vec3 = Vec3::new(-4.0, 5.0, 0.0);

/// What the trigger zone saw, kept on the `zone` entity.
#[derive(Clone, Debug, Default, serde::Serialize, serde::Deserialize)]
pub struct ZoneStats {
    /// Bodies that entered.
    pub entered: u32,
    /// Bodies that left.
    pub exited: u32,
}

impl Component for ZoneStats {
    const NAME: &'static str = "joints.zone";
}

/// The plugin.
#[derive(Default)]
pub struct Joints {
    zone: Option<Entity>,
    stats: ZoneStats,
}

fn body(
    ctx: &mut Ctx,
    name: &str,
    at: Vec3,
    half: Vec3,
    colour: Material,
) -> Result<Entity, CtxError> {
    ctx.spawn((
        Name::new(name),
        Transform::from_translation(at).with_scale(half * 2.0),
        MeshRenderer::new(MeshId::CUBE).with_material(colour),
        RigidBody::dynamic(),
        // A unit cube scaled to the body's size, like its mesh.
        Collider::cuboid(0.5, 0.5, 0.5).with_density(300.0),
    ))
}

impl Joints {
    fn build_scene(&mut self, ctx: &mut Ctx) -> Result<(), CtxError> {
        let eye = Vec3::new(0.0, 4.0, 12.0);
        let look = look_at_quat(eye, Vec3::new(0.0, 2.0, 0.0), Vec3::Y).inverse();
        let camera = ctx.spawn((
            Name::new("camera"),
            Transform::from_translation(eye).with_rotation(look),
            Camera::perspective(55f32.to_radians()),
        ))?;
        ctx.set_camera(camera)?;
        ctx.spawn((
            Name::new("sun"),
            Transform::IDENTITY.with_rotation(Quat::from_rotation_x(-0.9)),
            Light::sun(),
        ))?;
        ctx.spawn((
            Name::new("ground"),
            Transform::IDENTITY.with_scale(Vec3::new(20.0, 1.0, 20.0)),
            MeshRenderer::new(MeshId::PLANE).with_material(Material::color(0.4, 0.5, 0.4)),
            Collider::plane(),
        ))?;

        // The door: a post fixed in the world, the door hinged on its left edge to it.
        let wood = Material::color(0.6, 0.4, 0.2);
        let post = ctx.spawn((
            Name::new("post"),
            Transform::from_xyz(0.0, 1.1, 0.0).with_scale(Vec3::new(0.1, 2.2, 0.1)),
            MeshRenderer::new(MeshId::CUBE).with_material(wood),
            RigidBody::fixed(),
            Collider::cuboid(0.5, 0.5, 0.5),
        ))?;
        let door = body(
            ctx,
            "door",
            Vec3::new(0.55, 1.1, 0.0),
            Vec3::new(0.45, 1.0, 0.02),
            wood,
        )?;
        let hinge = Joint::revolute(JointTarget::Body(post), [0.0, 1.0, 0.0])
            .with_anchors([-0.5, 0.0, 0.0], [0.05, 0.0, 0.0])
            .with_limits(-0.1, 1.7)
            .with_motor(JointMotor::Position {
                target: DOOR_TARGET,
                hertz: 2.0,
                damping_ratio: 1.0,
                max_force: 2000.0,
            });
        ctx.set(door, hinge)?;

        // The chain: links end to end along +X from the anchor, each on a ball joint to the
        // one before (the first to the world); it swings down and hangs.
        let steel = Material::color(0.6, 0.6, 0.7);
        let mut previous: Option<Entity> = None;
        for k in 0..LINKS {
            let centre = CHAIN_ANCHOR + Vec3::X * LINK_LENGTH * (k as f32 + 0.5);
            let half = Vec3::new(LINK_LENGTH / 2.0, 0.04, 0.04);
            let link = body(ctx, &format!("link {k}"), centre, half, steel)?;
            let back = [-LINK_LENGTH / 2.0, 0.0, 0.0];
            let joint = match previous {
                None => {
                    Joint::spherical(JointTarget::World).with_anchors(back, CHAIN_ANCHOR.to_array())
                }
                Some(p) => Joint::spherical(JointTarget::Body(p))
                    .with_anchors(back, [LINK_LENGTH / 2.0, 0.0, 0.0]),
            };
            ctx.set(link, joint)?;
            previous = Some(link);
        }

        // The ragdoll: limbs hung from the torso on ball joints that bend at most 60°.
        let cloth = Material::color(0.3, 0.3, 0.8);
        let torso = body(
            ctx,
            "torso",
            Vec3::new(4.0, 3.0, 0.0),
            Vec3::new(0.25, 0.35, 0.12),
            cloth,
        )?;
        let limbs = [
            (
                "head",
                Vec3::new(0.0, 0.55, 0.0),
                Vec3::splat(0.15),
                [0.0, 0.35, 0.0],
            ),
            (
                "left arm",
                Vec3::new(-0.55, 0.15, 0.0),
                Vec3::new(0.25, 0.07, 0.07),
                [-0.25, 0.2, 0.0],
            ),
            (
                "right arm",
                Vec3::new(0.55, 0.15, 0.0),
                Vec3::new(0.25, 0.07, 0.07),
                [0.25, 0.2, 0.0],
            ),
            (
                "left leg",
                Vec3::new(-0.12, -0.7, 0.0),
                Vec3::new(0.09, 0.3, 0.09),
                [-0.12, -0.35, 0.0],
            ),
            (
                "right leg",
                Vec3::new(0.12, -0.7, 0.0),
                Vec3::new(0.09, 0.3, 0.09),
                [0.12, -0.35, 0.0],
            ),
        ];
        for (name, offset, half, on_torso) in limbs {
            let at = Vec3::new(4.0, 3.0, 0.0) + offset;
            let limb = body(ctx, name, at, half, cloth)?;
            // The limb's anchor is the torso's joint point in the limb's frame.
            let anchor = (Vec3::from(on_torso) - offset).to_array();
            let axis = (Vec3::from(on_torso) - offset).normalize_or(Vec3::Y);
            let mut joint =
                Joint::spherical(JointTarget::Body(torso)).with_anchors(anchor, on_torso);
            joint.kind = JointKind::Spherical {
                cone: 60f32.to_radians(),
            };
            joint.axis = axis.to_array();
            ctx.set(limb, joint)?;
        }

        // The trigger zone and a ball that falls through it.
        let zone = ctx.spawn((
            Name::new("zone"),
            Transform::from_xyz(0.0, 2.0, 3.0).with_scale(Vec3::splat(1.0)),
            RigidBody::fixed(),
            Collider::cuboid(0.5, 0.5, 0.5).with_sensor(true),
            ZoneStats::default(),
        ))?;
        self.zone = Some(zone);
        ctx.spawn((
            Name::new("ball"),
            Transform::from_xyz(0.0, 4.0, 3.0).with_scale(Vec3::splat(0.4)),
            MeshRenderer::new(MeshId::SPHERE).with_material(Material::color(0.9, 0.3, 0.2)),
            RigidBody::dynamic(),
            Collider::sphere(0.5),
        ))?;
        Ok(())
    }
}

impl Plugin for Joints {
    fn on_init(&mut self, ctx: &mut Ctx) {
        if let Err(error) = self.build_scene(ctx) {
            ctx.error(format!("could not build the scene: {error}"));
        }
    }

    fn on_event(&mut self, ctx: &mut Ctx, event: &Event) {
        let Some(zone) = self.zone else { return };
        match event {
            Event::Physics(PhysicsEvent::SensorEntered { sensor, .. }) if *sensor == zone => {
                self.stats.entered += 1;
            }
            Event::Physics(PhysicsEvent::SensorExited { sensor, .. }) if *sensor == zone => {
                self.stats.exited += 1;
            }
            _ => return,
        }
        ctx.set(zone, self.stats.clone()).ok();
    }
}

export_plugin!(Joints);
