//! The kinematic character controller against geometry with known answers: where a wall
//! stops a capsule and how far it slides along it, which steps and slopes it climbs, that it
//! stays on a slope going down with snap (and leaves it without), and that what it walks
//! into takes its speed.
mod common;
use common::*;
use onyx_physics::glam::{Quat, Vec3};
use onyx_physics::{
    BodyHandle, CharacterController, CharacterMove, ColliderDesc, PhysicsWorld, Pose, RigidBodyDesc,
};

const HALF_HEIGHT: f32 = 0.5;
const RADIUS: f32 = 0.3;
/// Capsule centre height standing on y = 0 with the default 1 cm gap.
const STANDING: f32 = HALF_HEIGHT + RADIUS + 0.01;

/// A world with a frictionless ground at y = 0 and a capsule character standing at `x`.
fn world_with_character(x: f32) -> (PhysicsWorld, BodyHandle) {
    let (mut w, _) = world_with_ground(0.0);
    let c = w.insert_body(RigidBodyDesc::kinematic().translation(Vec3::new(x, STANDING, 0.0)));
    w.insert_collider(ColliderDesc::capsule(HALF_HEIGHT, RADIUS), c);
    w.step();
    (w, c)
}

fn fixed_box(w: &mut PhysicsWorld, centre: Vec3, half: Vec3, rotation: Quat) {
    let b = w.insert_body(
        RigidBodyDesc::fixed()
            .translation(centre)
            .rotation(rotation),
    );
    w.insert_collider(ColliderDesc::cuboid(half.x, half.y, half.z), b);
}

/// Moves the character by `desired` per step for `steps` steps (the kinematic body follows);
/// returns every move.
fn walk(
    w: &mut PhysicsWorld,
    character: BodyHandle,
    desired: Vec3,
    steps: usize,
    controller: &CharacterController,
) -> Vec<CharacterMove> {
    let mut moves = Vec::new();
    for _ in 0..steps {
        let pose = w.body(character).unwrap().pose();
        let m = w
            .move_character(character, &pose, desired, controller)
            .expect("a character with a capsule");
        let next = Pose::new(pose.translation + m.translation, pose.rotation);
        w.body_mut(character).unwrap().set_next_kinematic_pose(next);
        w.step();
        moves.push(m);
    }
    moves
}

fn at(w: &PhysicsWorld, b: BodyHandle) -> Vec3 {
    w.body(b).unwrap().translation()
}

#[test]
fn a_wall_stops_the_character_at_its_gap_and_it_slides_along_it() {
    let (mut w, c) = world_with_character(0.0);
    // Wall face at x = 1.5.
    fixed_box(
        &mut w,
        Vec3::new(2.0, 1.0, 0.0),
        Vec3::new(0.5, 1.0, 5.0),
        Quat::IDENTITY,
    );
    let controller = CharacterController::default();
    let moves = walk(&mut w, c, Vec3::new(0.05, 0.0, 0.0), 60, &controller);
    let expected = 1.5 - RADIUS - controller.offset;
    let p = at(&w, c);
    assert!(
        (p.x - expected).abs() < 2e-3,
        "stopped at x = {}, expected {expected} (wall − radius − gap)",
        p.x
    );
    assert!((p.y - STANDING).abs() < 2e-3, "height {}", p.y);
    assert!(moves.last().unwrap().grounded, "it stands on the ground");
    assert!(!moves.last().unwrap().collisions.is_empty());
    // Walking diagonally into the wall keeps the part along it: 0.03 m per step in z.
    let moves = walk(&mut w, c, Vec3::new(0.03, 0.0, 0.03), 50, &controller);
    let q = at(&w, c);
    assert!(
        (q.z - p.z - 1.5).abs() < 0.015,
        "slid {} m along the wall, expected 1.5",
        q.z - p.z
    );
    assert!((q.x - expected).abs() < 2e-3, "left the wall: x = {}", q.x);
    assert!(moves.iter().all(|m| m.grounded));
}

/// A step of height `h` whose riser is at x = 1.
fn step_of(h: f32) -> (PhysicsWorld, BodyHandle) {
    let (mut w, c) = world_with_character(0.0);
    fixed_box(
        &mut w,
        Vec3::new(3.0, h / 2.0, 0.0),
        Vec3::new(2.0, h / 2.0, 2.0),
        Quat::IDENTITY,
    );
    w.step();
    (w, c)
}

#[test]
fn it_climbs_a_step_lower_than_the_step_height_and_not_a_higher_one() {
    let controller = CharacterController {
        step_height: 0.3,
        ..CharacterController::default()
    };
    let gravity = Vec3::new(0.04, -0.02, 0.0);
    let (mut w, c) = step_of(0.25);
    walk(&mut w, c, gravity, 60, &controller);
    let p = at(&w, c);
    assert!(
        p.x > 2.0 && (p.y - (0.25 + STANDING)).abs() < 5e-3,
        "a 25 cm step under a 30 cm step height is climbed: the character is at {p}, \
         expected x > 2 on top at y = {}",
        0.25 + STANDING
    );
    let (mut w, c) = step_of(0.4);
    walk(&mut w, c, gravity, 60, &controller);
    let p = at(&w, c);
    let stop = 1.0 - RADIUS - controller.offset;
    assert!(
        (p.x - stop).abs() < 5e-3 && (p.y - STANDING).abs() < 5e-3,
        "a 40 cm step is a wall: the character is at {p}, expected ({stop}, {STANDING})"
    );
}

/// A ramp rising toward +x at `angle` from its foot at x = 1.
fn ramp(w: &mut PhysicsWorld, angle: f32) {
    let along = Vec3::new(angle.cos(), angle.sin(), 0.0);
    let normal = Vec3::new(-angle.sin(), angle.cos(), 0.0);
    let foot = Vec3::new(1.0, 0.0, 0.0);
    fixed_box(
        w,
        foot + along * 5.0 - normal * 0.5,
        Vec3::new(5.0, 0.5, 2.0),
        Quat::from_rotation_z(angle),
    );
    w.step();
}

#[test]
fn it_walks_up_a_gentle_slope_and_not_a_steeper_one_than_its_largest() {
    let controller = CharacterController::default(); // 45°
    let desired = Vec3::new(0.05, -0.02, 0.0);
    for (degrees, climbs) in [(30.0f32, true), (60.0, false)] {
        let (mut w, c) = world_with_character(0.0);
        ramp(&mut w, degrees.to_radians());
        walk(&mut w, c, desired, 80, &controller);
        let p = at(&w, c);
        if climbs {
            // 4 m of intended walking: well up the slope, on it (its height at the
            // capsule's axis, plus the rounded bottom's (r + gap) / cos θ, minus r).
            let t = degrees.to_radians();
            let surface = (p.x - 1.0) * t.tan();
            let expected = surface + (RADIUS + controller.offset) / t.cos() + HALF_HEIGHT;
            assert!(
                p.x > 2.5 && (p.y - expected).abs() < 0.02,
                "{degrees}° is walkable: the character is at {p}, expected x > 2.5 at \
                 y = {expected}"
            );
        } else {
            assert!(
                p.x < 1.0 && p.y < STANDING + 0.1,
                "{degrees}° is steeper than 45°: the character must stay at its foot, it is \
                 at {p}"
            );
        }
    }
}

#[test]
fn snapping_keeps_it_on_a_slope_going_down_and_without_it_it_leaves_the_ground() {
    for snap in [0.2f32, 0.0] {
        let controller = CharacterController {
            snap_to_ground: snap,
            ..CharacterController::default()
        };
        let (mut w, c) = world_with_character(4.0);
        ramp(&mut w, 20f32.to_radians());
        // Land on the ramp first.
        let pose = w.body(c).unwrap().pose();
        w.body_mut(c)
            .unwrap()
            .set_pose(Pose::new(pose.translation + Vec3::Y * 2.0, pose.rotation));
        w.step();
        walk(&mut w, c, Vec3::new(0.0, -3.0, 0.0), 1, &controller);
        // Walk down it horizontally, 5 cm a step: 1.8 cm of drop each.
        let moves = walk(&mut w, c, Vec3::new(-0.05, 0.0, 0.0), 30, &controller);
        let grounded = moves.iter().filter(|m| m.grounded).count();
        if snap > 0.0 {
            assert_eq!(grounded, moves.len(), "with snap it stays on the slope");
        } else {
            assert!(
                grounded < moves.len() / 2,
                "without snap it walks off into the air: grounded in {grounded} of {} moves",
                moves.len()
            );
        }
    }
}

#[test]
fn it_gives_a_frictionless_box_it_walks_into_its_own_speed() {
    let (mut w, c) = world_with_character(0.0);
    let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(1.0, 0.25, 0.0)));
    w.insert_collider(ColliderDesc::cuboid(0.25, 0.25, 0.25).friction(0.0), b);
    run(&mut w, 10);
    let speed = 1.0;
    let dt = w.settings().dt;
    let controller = CharacterController::default();
    walk(&mut w, c, Vec3::new(speed * dt, 0.0, 0.0), 90, &controller);
    let v = w.body(b).unwrap().linvel();
    assert!(
        (v.x - speed).abs() < 0.1 * speed,
        "the box moves at {v}, expected {speed} m/s along x"
    );
    let gap = at(&w, b).x - 0.25 - (at(&w, c).x + RADIUS);
    assert!(
        gap > 0.0 && gap < 0.05,
        "the character walks right behind the box: gap {gap} m"
    );
}
