//! Bodies whose every rotation axis is locked: their contacts are solved without angular
//! rows (a linear batch), which must give what the full rows give when nothing turns.
mod common;
use common::*;
use onyx_physics::glam::{Quat, Vec3};
use onyx_physics::{
    BodyHandle, ColliderDesc, LockedAxes, PhysicsSettings, PhysicsWorld, RigidBodyDesc,
};

#[test]
fn locked_box_slides_v2_over_2_mu_g_and_never_turns() {
    let mu = 0.5;
    let (mut w, _) = world_with_ground(mu);
    let v0 = 10.0;
    let q0 = Quat::from_rotation_y(0.3);
    let b = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(0.0, 0.5, 0.0))
            .rotation(q0)
            .linvel(Vec3::X * v0)
            .lock_rotations(),
    );
    w.insert_collider(ColliderDesc::cuboid(0.5, 0.5, 0.5).friction(mu), b);
    run(&mut w, 300);
    let body = w.body(b).unwrap();
    let expected = v0 * v0 / (2.0 * mu * G);
    let x = body.translation().x;
    assert!(
        body.linvel().length() < 0.01,
        "box still moving at {}",
        body.linvel()
    );
    assert!(
        (x - expected).abs() < 0.03 * expected,
        "stop distance: measured {x}, expected {expected} ± 3%"
    );
    assert_eq!(body.angvel(), Vec3::ZERO, "a locked body spins");
    let turned = body.rotation().angle_between(q0);
    assert!(turned < 1e-6, "a locked body turned by {turned} rad");
}

/// Boxes and balls moving in the XY plane: a stack of three offset boxes, a box sliding into
/// it, balls dropped on the top box and on each other. Returns every body's position after
/// `steps`.
fn in_plane_scene(locks: LockedAxes, steps: usize) -> Vec<Vec3> {
    let (mut w, _) = world_with_ground(0.6);
    let mut bodies: Vec<BodyHandle> = Vec::new();
    let mut add = |w: &mut PhysicsWorld, desc: RigidBodyDesc, collider: ColliderDesc| {
        let b = w.insert_body(desc.locked_axes(locks));
        w.insert_collider(collider.friction(0.6), b);
        bodies.push(b);
    };
    for (k, dx) in [0.0, 0.2, 0.35].into_iter().enumerate() {
        add(
            &mut w,
            RigidBodyDesc::dynamic().translation(Vec3::new(dx, 0.5 + k as f32, 0.0)),
            ColliderDesc::cuboid(0.5, 0.5, 0.5),
        );
    }
    add(
        &mut w,
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(-4.0, 0.25, 0.0))
            .linvel(Vec3::X * 6.0),
        ColliderDesc::cuboid(0.25, 0.25, 0.25),
    );
    for k in 0..3 {
        add(
            &mut w,
            RigidBodyDesc::dynamic().translation(Vec3::new(0.1 * k as f32, 3.5 + k as f32, 0.0)),
            ColliderDesc::sphere(0.2),
        );
    }
    run(&mut w, steps);
    bodies
        .iter()
        .map(|&b| w.body(b).unwrap().translation())
        .collect()
}

#[test]
fn fully_locked_bodies_move_as_bodies_locked_against_every_in_plane_torque() {
    // Motion in the XY plane only turns bodies about Z (and about X through the boxes'
    // off-plane corners), never about Y: locking X and Z keeps the full rows but the same
    // motion, locking all three takes the linear batches.
    let linear = in_plane_scene(LockedAxes::ALL_ROTATIONS, 240);
    let full = in_plane_scene(LockedAxes::ROTATION_X | LockedAxes::ROTATION_Z, 240);
    for (k, (a, b)) in linear.iter().zip(&full).enumerate() {
        assert!(a.is_finite(), "body {k} at {a}");
        assert!(
            a.distance(*b) < 1e-3,
            "body {k}: {a} with every rotation locked, {b} with X and Z locked"
        );
    }
    // The scene did something: the slider hit the stack, the balls landed on top.
    assert!(
        linear[3].x > -2.0,
        "the sliding box stopped early: {}",
        linear[3]
    );
    assert!(linear[4].y < 3.4, "the balls never fell: {}", linear[4]);
}

#[test]
fn locked_box_rides_a_spinning_kinematic_platform() {
    // The platform turns, so the box's contacts keep their angular rows: friction must see
    // the platform's surface moving under the box and carry it round.
    let mut w = PhysicsWorld::new(PhysicsSettings::default());
    let omega = 1.0;
    let plat = w.insert_body(RigidBodyDesc::kinematic().angvel(Vec3::Y * omega));
    w.insert_collider(ColliderDesc::cuboid(5.0, 0.1, 5.0).friction(1.0), plat);
    let r = 2.0;
    let b = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(r, 0.35, 0.0))
            .lock_rotations(),
    );
    w.insert_collider(ColliderDesc::cuboid(0.25, 0.25, 0.25).friction(1.0), b);
    run(&mut w, 120); // 2 s: the platform turned 2 rad
    let body = w.body(b).unwrap();
    let p = body.translation();
    let radius = (p.x * p.x + p.z * p.z).sqrt();
    let angle = (-p.z).atan2(p.x);
    assert!(
        (radius - r).abs() < 0.1,
        "the box left its circle: radius {radius}, expected {r}"
    );
    assert!(
        (angle - 2.0 * omega).abs() < 0.15,
        "the box went round by {angle} rad, the platform by {}",
        2.0 * omega
    );
    let speed = body.linvel().length();
    assert!(
        (speed - omega * r).abs() < 0.1 * omega * r,
        "carried at {speed} m/s, expected ωr = {}",
        omega * r
    );
    let turned = body.rotation().angle_between(Quat::IDENTITY);
    assert!(turned < 1e-6, "a locked body turned by {turned} rad");
}
