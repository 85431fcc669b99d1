//! Speed caps: bodies are clamped to `max_linear_speed` / `max_angular_speed`, and the first
//! time each body hits each cap is reported in the step output (hitting a cap used to be
//! silent, and a scene could not raise it).
use onyx_physics::glam::Vec3;
use onyx_physics::{
    ColliderDesc, PhysicsSettings, PhysicsWorld, RigidBodyDesc, SpeedCap, SpeedCapHit,
};

fn zero_g() -> PhysicsSettings {
    PhysicsSettings {
        gravity: Vec3::ZERO,
        ..Default::default()
    }
}

#[test]
fn a_body_faster_than_the_cap_is_slowed_to_it_and_reported_once() {
    let s = zero_g();
    let mut w = PhysicsWorld::new(s);
    let b = w.insert_body(RigidBodyDesc::dynamic().linvel(Vec3::X * 2.0 * s.max_linear_speed));
    w.insert_collider(ColliderDesc::sphere(0.1), b);
    let first: Vec<SpeedCapHit> = w.step().speed_caps.clone();
    let speed = w.body(b).unwrap().linvel().length();
    println!(
        "speed after one step: {speed} m/s, cap {} m/s",
        s.max_linear_speed
    );
    assert!(
        (speed - s.max_linear_speed).abs() < 1e-3 * s.max_linear_speed,
        "speed {speed}, expected the cap {}",
        s.max_linear_speed
    );
    assert_eq!(
        first,
        vec![SpeedCapHit {
            body: b,
            cap: SpeedCap::Linear,
            limit: s.max_linear_speed
        }]
    );
    // Clamped again (it is set back above the cap), never reported again.
    for _ in 0..10 {
        w.body_mut(b)
            .unwrap()
            .set_linvel(Vec3::X * 3.0 * s.max_linear_speed);
        let out = w.step();
        assert!(
            out.speed_caps.is_empty(),
            "reported twice: {:?}",
            out.speed_caps
        );
        assert_eq!(out.counters.speed_capped, 1);
    }
}

#[test]
fn a_raised_cap_lets_the_body_keep_its_speed() {
    let s = PhysicsSettings {
        max_linear_speed: 5_000.0,
        max_angular_speed: 1_000.0,
        ..zero_g()
    };
    let mut w = PhysicsWorld::new(s);
    let b = w.insert_body(
        RigidBodyDesc::dynamic()
            .linvel(Vec3::X * 2_000.0)
            .angvel(Vec3::Y * 500.0),
    );
    w.insert_collider(ColliderDesc::sphere(0.1), b);
    let out = w.step();
    assert!(out.speed_caps.is_empty(), "{:?}", out.speed_caps);
    let body = w.body(b).unwrap();
    println!(
        "speed {} m/s, spin {} rad/s",
        body.linvel().length(),
        body.angvel().length()
    );
    assert!((body.linvel().length() - 2_000.0).abs() < 1e-2);
    assert!((body.angvel().length() - 500.0).abs() < 1e-3);
}

#[test]
fn the_spin_cap_is_reported_as_angular() {
    let s = zero_g();
    let mut w = PhysicsWorld::new(s);
    let b = w.insert_body(RigidBodyDesc::dynamic().angvel(Vec3::new(300.0, 0.0, 400.0)));
    w.insert_collider(ColliderDesc::sphere(0.1), b);
    let hits = w.step().speed_caps.clone();
    let spin = w.body(b).unwrap().angvel().length();
    println!(
        "spin after one step: {spin} rad/s, cap {}",
        s.max_angular_speed
    );
    assert!((spin - s.max_angular_speed).abs() < 1e-3 * s.max_angular_speed);
    assert_eq!(hits.len(), 1);
    assert_eq!(hits[0].cap, SpeedCap::Angular);
    assert_eq!(hits[0].cap.setting(), "max_angular_speed");
}

/// The velocities a step leaves are within the caps, also where the passes that run after
/// the last substep's move (relax, restitution) raised them: a capsule struck off centre at
/// 1,000 m/s by a wall moving into it was left spinning at about 7,000 rad/s under the
/// 200 rad/s cap, and the contact held it by that spin while CCD froze its turn, until the
/// wall passed it.
#[test]
fn no_step_leaves_a_body_past_a_cap() {
    for preset in onyx_physics::PhysicsPreset::ALL {
        let s = PhysicsSettings {
            gravity: Vec3::ZERO,
            sleep_enabled: false,
            ..preset.settings()
        };
        let mut w = PhysicsWorld::new(s);
        let wall = w.insert_body(
            RigidBodyDesc::kinematic()
                .translation(Vec3::new(20.0, 1.0, 0.0))
                .linvel(Vec3::X * -30.0),
        );
        w.insert_collider(ColliderDesc::cuboid(0.005, 1.0, 1.0), wall);
        let b = w.insert_body(
            RigidBodyDesc::dynamic()
                .translation(Vec3::Y)
                .linvel(Vec3::X * 1_000.0)
                .angvel(Vec3::new(3.0, 11.0, -7.0))
                .ccd_enabled(true),
        );
        w.insert_collider(ColliderDesc::capsule(0.05, 0.01), b);
        let (mut fastest, mut fastest_spin) = (0.0f32, 0.0f32);
        for _ in 0..(0.5 / s.dt) as usize {
            w.step();
            let body = w.body(b).unwrap();
            fastest = fastest.max(body.linvel().length());
            fastest_spin = fastest_spin.max(body.angvel().length());
        }
        println!(
            "{preset}: fastest {fastest} m/s (cap {}), spin {fastest_spin} rad/s (cap {})",
            s.max_linear_speed, s.max_angular_speed
        );
        assert!(fastest <= s.max_linear_speed * (1.0 + 1e-5));
        assert!(
            fastest_spin <= s.max_angular_speed * (1.0 + 1e-5),
            "{preset}: left spinning at {fastest_spin} rad/s, cap {}",
            s.max_angular_speed
        );
    }
}
