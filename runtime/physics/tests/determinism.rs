//! Determinism: the same scene with the same inputs gives bit-identical state after 10,000
//! steps, in two runs in one process and in another process (the test runs itself as a
//! child). What it covers and what would break it is in `docs/physics-accuracy.md`
//! ("Determinism").

mod common;

use common::Rng;
use onyx_physics::glam::{Quat, Vec3};
use onyx_physics::{ColliderDesc, JointDesc, PhysicsPreset, PhysicsWorld, RigidBodyDesc};

/// Steps of each run (the figure).
const STEPS: usize = 10_000;

/// The environment variable that makes the test print its hash instead of spawning a child.
const CHILD: &str = "ONYX_DETERMINISM_CHILD";

/// A pile of boxes, spheres and capsules poured on the ground onto a hinged chain, a ball
/// joint pendulum and a sleeping corner: contacts, friction, restitution, joints, sleep and
/// wake all take part. `nudge` moves one body by one ulp (to show the hash sees it).
fn scene(nudge: bool) -> PhysicsWorld {
    let mut w = PhysicsWorld::new(PhysicsPreset::Balanced.settings());
    let ground = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(ColliderDesc::cuboid(20.0, 0.5, 20.0).friction(0.6), ground);
    w.insert_collider(
        ColliderDesc::cuboid(0.5, 2.0, 6.0).translation(Vec3::new(-4.0, 2.0, 0.0)),
        ground,
    );
    let mut rng = Rng(0x5eed_0f0a_1e00);
    for i in 0..48 {
        let mut p = Vec3::new(0.0, 1.5 + 0.9 * i as f32, 0.0) + rng.vec3(-1.5, 1.5);
        if nudge && i == 17 {
            p.x = f32::from_bits(p.x.to_bits() + 1);
        }
        let body = w.insert_body(
            RigidBodyDesc::dynamic()
                .translation(p)
                .rotation(rng.quat())
                .angvel(rng.vec3(-2.0, 2.0)),
        );
        let collider = match i % 3 {
            0 => ColliderDesc::cuboid(0.3, 0.2, 0.4),
            1 => ColliderDesc::sphere(0.3),
            _ => ColliderDesc::capsule(0.25, 0.2),
        };
        w.insert_collider(collider.friction(0.5).restitution(0.2), body);
    }
    // A 10-link hinged chain hung from the world, swinging into the pile.
    let mut previous = None;
    for k in 0..10 {
        let link = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(
            3.0 + 0.5 * k as f32,
            6.0,
            2.0,
        )));
        w.insert_collider(ColliderDesc::cuboid(0.25, 0.05, 0.05), link);
        let joint = JointDesc::revolute(Vec3::Z).local_anchor_b(Vec3::new(-0.25, 0.0, 0.0));
        let joint = match previous {
            None => joint.local_anchor_a(Vec3::new(2.75, 6.0, 2.0)),
            Some(_) => joint.local_anchor_a(Vec3::new(0.25, 0.0, 0.0)),
        };
        w.insert_joint(joint, previous, link).expect("valid joint");
        previous = Some(link);
    }
    // A ball-joint pendulum with a cone limit.
    let bob = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(-2.0, 5.0, -3.0))
            .rotation(Quat::from_rotation_z(0.7)),
    );
    w.insert_collider(ColliderDesc::sphere(0.3), bob);
    let ball = JointDesc::spherical()
        .local_anchor_a(Vec3::new(-2.0, 7.0, -3.0))
        .local_anchor_b(Vec3::new(0.0, 2.0, 0.0))
        .cone_limit(1.0);
    w.insert_joint(ball, None, bob).expect("valid joint");
    w
}

/// FNV-1a over the bits of every body's pose and velocities, in handle order.
fn state_hash(w: &PhysicsWorld) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let mut eat = |x: f32| {
        for byte in x.to_bits().to_le_bytes() {
            h ^= u64::from(byte);
            h = h.wrapping_mul(0x0100_0000_01b3);
        }
    };
    for (_, b) in w.bodies().iter() {
        let p = b.translation();
        let q = b.rotation();
        let v = b.linvel();
        let o = b.angvel();
        for x in [
            p.x, p.y, p.z, q.x, q.y, q.z, q.w, v.x, v.y, v.z, o.x, o.y, o.z,
        ] {
            eat(x);
        }
    }
    h
}

fn run(nudge: bool) -> u64 {
    let mut w = scene(nudge);
    for _ in 0..STEPS {
        w.step();
    }
    state_hash(&w)
}

#[test]
fn two_runs_give_bit_identical_state_after_ten_thousand_steps() {
    if std::env::var_os(CHILD).is_some() {
        return;
    }
    let first = run(false);
    assert_eq!(first, run(false), "the second run differs");
    // The hash sees a one-ulp change in one body's start (so the equality above means
    // something).
    assert_ne!(first, run(true), "a one-ulp nudge left the hash unchanged");
}

#[test]
fn another_process_gives_the_same_state() {
    if std::env::var_os(CHILD).is_some() {
        println!("STATE_HASH={:016x}", run(false));
        return;
    }
    let exe = std::env::current_exe().expect("test binary path");
    let out = std::process::Command::new(exe)
        .args([
            "--exact",
            "another_process_gives_the_same_state",
            "--nocapture",
            "--test-threads",
            "1",
        ])
        .env(CHILD, "1")
        .output()
        .expect("the test binary runs as a child");
    assert!(out.status.success(), "child failed: {out:?}");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let child = stdout
        .lines()
        .find_map(|l| l.split_once("STATE_HASH=").map(|(_, hash)| hash.trim()))
        .unwrap_or_else(|| panic!("no hash in the child's output:\n{stdout}"));
    assert_eq!(child, format!("{:016x}", run(false)));
}
