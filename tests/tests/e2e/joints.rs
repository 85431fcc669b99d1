//! `Joint` components and collision groups from scene files, simulated by the host, against
//! analytic answers: a hinged pendulum's quarter period, a door hinged to a moving frame, a
//! weld that breaks, a bullet that flies through its shooter and stops on a wall.

use std::path::{Path, PathBuf};

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::{Collider, Joint, JointTarget, RigidBody, Transform};
use onyx_runtime::HeadlessHost;

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// The exact period of a simple pendulum of length `l` from amplitude `theta0`:
/// `4 √(l/g) K(sin(θ₀/2))` (K by the arithmetic–geometric mean).
fn exact_period(l: f64, theta0: f64, g: f64) -> f64 {
    let k = (theta0 / 2.0).sin();
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    for _ in 0..30 {
        (a, b) = ((a + b) / 2.0, (a * b).sqrt());
    }
    4.0 * (l / g).sqrt() * std::f64::consts::PI / (2.0 * a)
}

/// A 1 m pendulum released horizontal, hinged to the world by a scene file's `Joint`:
/// it keeps its length and first reaches the bottom after a quarter of the exact period.
#[test]
fn a_hinged_pendulum_from_a_scene_file_swings_at_the_exact_period() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "pendulum.ron",
        r#"(version: 2, physics: Some((preset: Precise, sleep_enabled: Some(false))), entities: [
            (name: Some("bob"), transform: Some((translation: (1.0, 2.0, 0.0))),
             rigid_body: Some((kind: Dynamic)), collider: Some((shape: Sphere(radius: 0.02))),
             joint: Some((kind: Revolute, axis: (0.0, 0.0, 1.0), anchor: (-1.0, 0.0, 0.0),
                          other_anchor: (0.0, 2.0, 0.0)))),
        ])"#,
    );
    let mut host = HeadlessHost::new();
    host.load_scene(&path).unwrap();
    let (bob, joint) = host.find::<Joint>("bob").unwrap();
    assert_eq!(joint.other, JointTarget::World);
    let dt = 1.0 / 120.0;
    host.set_frame_time(dt);
    let pivot = Vec3::new(0.0, 2.0, 0.0);
    let (mut t, mut prev_x, mut worst) = (0.0f64, 1.0f32, 0.0f32);
    let mut quarter = None;
    while t < 2.0 && quarter.is_none() {
        host.step(1);
        t += dt;
        let p = host.get::<Transform>(bob).unwrap().translation;
        worst = worst.max(((p - pivot).length() - 1.0).abs());
        if prev_x > 0.0 && p.x <= 0.0 {
            quarter = Some(t - dt + dt * f64::from(prev_x / (prev_x - p.x)));
        }
        prev_x = p.x;
    }
    let quarter = quarter.expect("the pendulum never reached the bottom");
    let expected = exact_period(1.0, std::f64::consts::FRAC_PI_2, 9.81) / 4.0;
    assert!(
        (quarter - expected).abs() / expected < 0.005,
        "quarter period {quarter} s, exact {expected} s"
    );
    assert!(worst < 2e-3, "the hinge let the bob stray {worst} m");
}

/// A door hinged to a frame that the scene moves (kinematic, 1 m/s along X): the door's
/// hinge edge stays on the frame's, and the door turns freely about the vertical axis only.
/// A weld that breaks past 50 N lets a 10 kg block fall; one that breaks past 150 N holds it.
#[test]
fn a_door_follows_its_frame_and_an_overloaded_weld_breaks() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "door.ron",
        r#"(version: 2, physics: Some((preset: Balanced, sleep_enabled: Some(false))), entities: [
            (id: Some(1), name: Some("frame"), transform: Some((translation: (0.0, 1.0, 0.0))),
             rigid_body: Some((kind: Kinematic, linear_velocity: (1.0, 0.0, 0.0))),
             collider: Some((shape: Box(half_extents: (0.05, 1.0, 0.05)))) ),
            (name: Some("door"), transform: Some((translation: (0.5, 1.0, 0.0))),
             rigid_body: Some((kind: Dynamic, angular_velocity: (0.0, 1.0, 0.0))),
             collider: Some((shape: Box(half_extents: (0.45, 0.9, 0.02)))),
             joint: Some((kind: Revolute, other: Some(1), axis: (0.0, 1.0, 0.0),
                          anchor: (-0.5, 0.0, 0.0), other_anchor: (0.0, 0.0, 0.0)))),
            (name: Some("block"), transform: Some((translation: (5.0, 3.0, 0.0))),
             rigid_body: Some((kind: Dynamic, mass: 10.0)),
             collider: Some((shape: Box(half_extents: (0.1, 0.1, 0.1)))),
             joint: Some((kind: Fixed, other_anchor: (5.0, 3.0, 0.0), break_force: 50.0))),
            (name: Some("held"), transform: Some((translation: (8.0, 3.0, 0.0))),
             rigid_body: Some((kind: Dynamic, mass: 10.0)),
             collider: Some((shape: Box(half_extents: (0.1, 0.1, 0.1)))),
             joint: Some((kind: Fixed, other_anchor: (8.0, 3.0, 0.0), break_force: 150.0))),
        ])"#,
    );
    let mut host = HeadlessHost::new();
    host.load_scene(&path).unwrap();
    host.set_frame_time(1.0 / 60.0);
    host.step(1);
    // A 10 kg block weighs 98.1 N: the 50 N weld breaks on the first step, the 150 N one
    // holds.
    let (block, joint) = host.find::<Joint>("block").unwrap();
    assert!(joint.broken, "the weld should have broken: {joint:?}");
    let (held, joint) = host.find::<Joint>("held").unwrap();
    assert!(!joint.broken, "the 150 N weld broke under 98 N");
    host.step(59);
    let (door, _) = host.find::<Transform>("door").unwrap();
    let (_, frame) = host.find::<Transform>("frame").unwrap();
    let door_t = host.get::<Transform>(door).unwrap();
    let hinge = door_t.translation + door_t.rotation * Vec3::new(-0.5, 0.0, 0.0);
    assert!(
        (hinge - frame.translation).length() < 5e-3,
        "hinge edge at {hinge}, frame at {}",
        frame.translation
    );
    // After 1 s at 1 m/s the frame is at x = 1.
    assert!(
        (frame.translation.x - 1.0).abs() < 0.02,
        "frame at {}",
        frame.translation
    );
    // Only turned about Y: the door's up axis stays up (its 636 N weight hangs on the
    // hinge 0.5 m out; a soft joint sags a little).
    let up = door_t.rotation * Vec3::Y;
    assert!(up.y > 0.9995, "the door tilted: up = {up}");
    // The door was spun at 1 rad/s about its centre; the hinge keeps its angular momentum
    // about the hinge line: ω' = ω I_c / (I_c + m d²) with I_c = m (hx² + hz²) / 3 and
    // d = 0.5 m, whatever the frame does (its motion only pushes through the hinge line).
    let side = door_t.rotation * Vec3::X;
    let angle = (-side.z).atan2(side.x);
    let i_c = (0.45f32 * 0.45 + 0.02 * 0.02) / 3.0;
    let expected = 1.0 * i_c / (i_c + 0.25);
    assert!(
        (angle - expected).abs() < 0.02 * expected,
        "the door turned {angle} rad in 1 s, expected {expected}"
    );
    // The broken block fell freely for about a second (g t² / 2 ≈ 4.9 m), the held one
    // hangs where it was.
    let block_t = host.get::<Transform>(block).unwrap();
    assert!(
        block_t.translation.y < 3.0 - 4.0,
        "block at {}",
        block_t.translation
    );
    let held_t = host.get::<Transform>(held).unwrap();
    assert!(
        (held_t.translation - Vec3::new(8.0, 3.0, 0.0)).length() < 0.01,
        "held block at {}",
        held_t.translation
    );
}

/// A bullet in group 2 whose filter leaves out group 1 flies through the shooter (group 1)
/// at its launch speed and stops on the wall; an unfiltered bullet beside it hits the
/// shooter's twin. The groups round-trip through the scene file.
#[test]
fn a_filtered_bullet_flies_through_its_shooter_and_stops_on_the_wall() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "range.ron",
        r#"(version: 2, physics: Some((gravity: Some((0.0, 0.0, 0.0)), sleep_enabled: Some(false))), entities: [
            (name: Some("wall"), transform: Some((translation: (5.0, 0.0, 0.0))),
             rigid_body: Some((kind: Static)), collider: Some((shape: Box(half_extents: (0.5, 4.0, 4.0))))),
            (name: Some("shooter"), transform: Some((translation: (0.0, 0.0, 0.0))),
             rigid_body: Some((kind: Dynamic)),
             collider: Some((shape: Box(half_extents: (0.5, 0.5, 0.5)), memberships: 1))),
            (name: Some("bullet"), transform: Some((translation: (-1.0, 0.0, 0.0))),
             rigid_body: Some((kind: Dynamic, linear_velocity: (10.0, 0.0, 0.0))),
             collider: Some((shape: Sphere(radius: 0.1), memberships: 2, filter: 4294967294))),
            (name: Some("twin"), transform: Some((translation: (0.0, 2.0, 0.0))),
             rigid_body: Some((kind: Dynamic)),
             collider: Some((shape: Box(half_extents: (0.5, 0.5, 0.5)), memberships: 1))),
            (name: Some("plain bullet"), transform: Some((translation: (-1.0, 2.0, 0.0))),
             rigid_body: Some((kind: Dynamic, linear_velocity: (10.0, 0.0, 0.0))),
             collider: Some((shape: Sphere(radius: 0.1)))),
        ])"#,
    );
    let mut host = HeadlessHost::new();
    host.load_scene(&path).unwrap();
    let (bullet, collider) = host.find::<Collider>("bullet").unwrap();
    assert_eq!((collider.memberships, collider.filter), (2, !1));
    host.set_frame_time(1.0 / 60.0);
    host.step(20);
    let rb = host.get::<RigidBody>(bullet).unwrap();
    assert!(
        (rb.linear_velocity.x - 10.0).abs() < 1e-3,
        "the filtered bullet slowed to {}",
        rb.linear_velocity
    );
    let (_, shooter) = host.find::<RigidBody>("shooter").unwrap();
    assert!(
        shooter.linear_velocity.length() < 1e-6,
        "the shooter was hit"
    );
    let (_, twin) = host.find::<RigidBody>("twin").unwrap();
    assert!(
        twin.linear_velocity.x > 0.01,
        "the plain bullet missed the twin"
    );
    host.step(60);
    let p = host.get::<Transform>(bullet).unwrap().translation;
    assert!(
        p.x > 4.0 && p.x < 4.41,
        "the filtered bullet is at {p}, not on the wall"
    );
}
