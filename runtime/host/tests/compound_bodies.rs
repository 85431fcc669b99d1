//! Compound bodies and scaled colliders in the host: every collider on an entity or on its
//! descendants without a `RigidBody` of their own belongs to the nearest ancestor's body
//! (mass, centre of mass and inertia combined), and colliders follow their entity's scale.
//! Checked against statics: where a body balances, where it rests.

use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::{Collider, Ctx, Entity, Flow, Name, Parent, Plugin, RigidBody, Transform};
use onyx_runtime::HeadlessHost;

type Script = Box<dyn FnMut(&mut Ctx, u64) + Send>;

/// Runs a closure each frame with the frame number.
struct Scripted {
    script: Script,
    frame: u64,
}

impl Plugin for Scripted {
    fn on_update(&mut self, ctx: &mut Ctx, _: f32) -> Flow {
        (self.script)(ctx, self.frame);
        self.frame += 1;
        Flow::Continue
    }
}

fn run(frames: u32, script: impl FnMut(&mut Ctx, u64) + Send + 'static) -> HeadlessHost {
    let mut host = HeadlessHost::new();
    let plugin = Scripted {
        script: Box::new(script),
        frame: 0,
    };
    host.add_plugin("scripted", plugin).unwrap();
    host.step(frames);
    host
}

/// The world position of `entity`: its transform with every ancestor's applied.
fn world_position(host: &HeadlessHost, entity: Entity) -> Vec3 {
    let mut affine = onyx_plugin_api::glam::Affine3A::IDENTITY;
    let mut e = Some(entity);
    while let Some(x) = e {
        affine = host.get::<Transform>(x).expect("a transform").affine() * affine;
        e = host.get::<Parent>(x).map(|p| p.0);
    }
    affine.translation.into()
}

/// An L of two boxes (a 2 m bar on the body's entity, a 1 m post at one end on a child
/// entity with no body of its own) laid across the edge of a ledge at x = 0.
///
/// Bar: 2 × 0.2 × 1 m at the body's origin (0.4 ρ); post: 0.2 × 1 × 1 m with its centre 0.9 m
/// along and 0.6 m up (0.2 ρ). The combined centre of mass is 0.3 m from the origin toward the
/// post: the L stays when that lies over the ledge, and tips off when it does not, whatever
/// the bar alone would do.
fn l_on_a_ledge(body_x: f32, post_side: f32) -> (Vec3, Quat) {
    let host = run(150, move |ctx, frame| {
        if frame != 0 {
            return;
        }
        ctx.spawn((
            Name::new("ledge"),
            Transform::from_xyz(-5.0, -0.5, 0.0),
            Collider::cuboid(5.0, 0.5, 5.0),
        ))
        .unwrap();
        let l = ctx
            .spawn((
                Name::new("L"),
                Transform::from_xyz(body_x, 0.1, 0.0),
                RigidBody::dynamic(),
                Collider::cuboid(1.0, 0.1, 0.5),
            ))
            .unwrap();
        ctx.spawn((
            Name::new("post"),
            Transform::from_xyz(0.9 * post_side, 0.6, 0.0),
            Parent(l),
            Collider::cuboid(0.1, 0.5, 0.5),
        ))
        .unwrap();
    });
    let (_, t) = host.find::<Transform>("L").unwrap();
    (t.translation, t.rotation)
}

#[test]
fn an_l_of_two_boxes_balances_where_its_combined_centre_of_mass_says() {
    // Centre of mass at x = body_x + 0.3 · post_side.
    let cases = [
        // (body x, post side, centre of mass): the last two are where the bar alone would
        // do the opposite (stay at x = -0.2, tip at x = 0.2).
        (-0.4, 1.0, -0.1),
        (-0.2, 1.0, 0.1),
        (0.2, -1.0, -0.1),
    ];
    for (body_x, side, com) in cases {
        let (p, q) = l_on_a_ledge(body_x, side);
        let tilt = q.angle_between(Quat::IDENTITY).to_degrees();
        if com < 0.0 {
            assert!(
                (p.y - 0.1).abs() < 0.01 && tilt < 1.0,
                "centre of mass at x = {com} is over the ledge: the L must rest flat, \
                 it is at {p} tilted {tilt}°"
            );
        } else {
            assert!(
                p.y < -0.5 && tilt > 20.0,
                "centre of mass at x = {com} is past the edge: the L must tip off, \
                 it is at {p} tilted {tilt}°"
            );
        }
    }
}

#[test]
fn a_collider_on_a_child_moves_with_its_parents_body_and_holds_it_up() {
    // A small ball on the body's entity, a 1 m box 1 m below it on a child: the body comes
    // to rest on the child's box, 1.5 m up, and a ray names the child.
    let host = run(150, |ctx, frame| {
        if frame != 0 {
            return;
        }
        ctx.spawn((Name::new("ground"), Transform::IDENTITY, Collider::plane()))
            .unwrap();
        let body = ctx
            .spawn((
                Name::new("body"),
                Transform::from_xyz(0.0, 4.0, 0.0),
                RigidBody::dynamic(),
                Collider::sphere(0.1),
            ))
            .unwrap();
        ctx.spawn((
            Name::new("foot"),
            Transform::from_xyz(0.0, -1.0, 0.0),
            Parent(body),
            Collider::cuboid(0.5, 0.5, 0.5),
        ))
        .unwrap();
    });
    let (_, t) = host.find::<Transform>("body").unwrap();
    assert!(
        (t.translation.y - 1.5).abs() < 0.01,
        "the body rests on its child's box at y = 1.5, it is at {}",
        t.translation
    );
    let (foot, _) = host.find::<Transform>("foot").unwrap();
    let foot_at = world_position(&host, foot);
    assert!(
        (foot_at.y - 0.5).abs() < 0.01,
        "the child's box moved down with the body to y = 0.5, it is at {foot_at}"
    );
    let hit = host
        .host()
        .physics()
        .raycast(Vec3::new(0.0, 0.75, 5.0), Vec3::NEG_Z, 10.0)
        .expect("the ray meets the child's box");
    assert_eq!(hit.entity, foot, "{hit:?}");
    assert!((hit.distance - 4.5).abs() < 1e-3, "{hit:?}");
}

#[test]
fn a_scaled_box_and_a_scaled_ball_rest_at_their_scaled_heights() {
    let host = run(150, |ctx, frame| {
        if frame != 0 {
            return;
        }
        ctx.spawn((Name::new("ground"), Transform::IDENTITY, Collider::plane()))
            .unwrap();
        ctx.spawn((
            Name::new("tall box"),
            Transform::from_xyz(0.0, 3.0, 0.0).with_scale(Vec3::new(1.0, 3.0, 2.0)),
            RigidBody::dynamic(),
            Collider::cuboid(0.5, 0.5, 0.5),
        ))
        .unwrap();
        // Scaled under a scaled parent: 0.25 × 2 × 2 = 1 m.
        let holder = ctx
            .spawn((
                Name::new("holder"),
                Transform::from_xyz(5.0, 0.0, 0.0).with_scale(Vec3::splat(2.0)),
            ))
            .unwrap();
        ctx.spawn((
            Name::new("big ball"),
            Transform::from_xyz(0.0, 2.0, 0.0).with_scale(Vec3::splat(2.0)),
            Parent(holder),
            RigidBody::dynamic(),
            Collider::sphere(0.25),
        ))
        .unwrap();
    });
    let (_, t) = host.find::<Transform>("tall box").unwrap();
    assert!(
        (t.translation.y - 1.5).abs() < 0.01,
        "a unit box scaled 3× in y rests with its centre 1.5 m up, it is at {}",
        t.translation
    );
    let (ball, _) = host.find::<Transform>("big ball").unwrap();
    let at = world_position(&host, ball);
    assert!(
        (at.y - 1.0).abs() < 0.01,
        "a 0.25 m ball scaled 4× rests with its centre 1 m up, it is at {at}"
    );
}

#[test]
fn a_ball_under_a_non_uniform_scale_stays_round_and_is_warned_about_once_by_name() {
    let host = run(120, |ctx, frame| {
        if frame != 0 {
            return;
        }
        ctx.spawn((Name::new("ground"), Transform::IDENTITY, Collider::plane()))
            .unwrap();
        ctx.spawn((
            Name::new("egg"),
            Transform::from_xyz(0.0, 3.0, 0.0).with_scale(Vec3::new(1.0, 2.0, 1.0)),
            RigidBody::dynamic(),
            Collider::sphere(0.5),
        ))
        .unwrap();
    });
    let (_, t) = host.find::<Transform>("egg").unwrap();
    assert!(
        (t.translation.y - 1.0).abs() < 0.01,
        "the ball takes the largest component (radius 1 m) and rests 1 m up: {}",
        t.translation
    );
    let warnings = onyx_runtime::console::console_log()
        .since(0)
        .into_iter()
        .filter(|l| l.message.contains("`egg`") && l.message.contains("non-uniform scale"))
        .count();
    assert_eq!(warnings, 1, "one warning naming the entity");
}
