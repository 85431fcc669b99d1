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
