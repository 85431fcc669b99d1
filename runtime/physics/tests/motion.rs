//! Free motion: gravity, projectiles, forces, locks, rigid-body rotation.
mod common;
use common::*;
use onyx_physics::glam::{Mat3, Quat, Vec3};
use onyx_physics::{ColliderDesc, LockedAxes, PhysicsSettings, PhysicsWorld, RigidBodyDesc};

#[test]
fn free_fall_matches_half_g_t_squared() {
    let mut w = PhysicsWorld::default();
    let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, 100.0, 0.0)));
    w.insert_collider(ColliderDesc::sphere(0.5), b);
    run(&mut w, 60); // 1 s
    let t = 1.0;
    let y = w.body(b).unwrap().translation().y;
    let v = w.body(b).unwrap().linvel().y;
    let y_exp = 100.0 - 0.5 * G * t * t;
    // Semi-implicit Euler with h = dt/4 errs by g·h·t/2 ≈ 0.02 m after 1 s.
    assert!(
        (y - y_exp).abs() < 0.03,
        "y after 1 s: measured {y}, expected {y_exp} ± 0.03"
    );
    assert!(
        (v + G * t).abs() < 1e-3,
        "vy after 1 s: measured {v}, expected {} ± 1e-3",
        -G * t
    );
}

#[test]
fn projectile_range_matches_v2_sin2theta_over_g() {
    let mut w = PhysicsWorld::default();
    let theta = 30f32.to_radians();
    let v0 = 20.0;
    let b = w.insert_body(RigidBodyDesc::dynamic().linvel(Vec3::new(
        v0 * theta.cos(),
        v0 * theta.sin(),
        0.0,
    )));
    w.insert_collider(ColliderDesc::sphere(0.1), b);
    let mut prev = w.body(b).unwrap().translation();
    let mut range = None;
    for _ in 0..600 {
        w.step();
        let p = w.body(b).unwrap().translation();
        if prev.y > 0.0 && p.y <= 0.0 {
            let f = prev.y / (prev.y - p.y);
            range = Some(prev.x + (p.x - prev.x) * f);
            break;
        }
        prev = p;
    }
    let expected = v0 * v0 * (2.0 * theta).sin() / G;
    let r = range.expect("projectile never came back to y = 0");
    assert!(
        (r - expected).abs() < 0.005 * expected,
        "range: measured {r}, expected {expected} ± 0.5%"
    );
}

#[test]
fn gravity_scale_and_disable_change_acceleration() {
    let mut w = PhysicsWorld::default();
    let half = w.insert_body(RigidBodyDesc::dynamic().gravity_scale(0.5));
    w.insert_collider(ColliderDesc::sphere(0.1), half);
    let off = w.insert_body(
        RigidBodyDesc::dynamic()
            .gravity_enabled(false)
            .translation(Vec3::X * 5.0),
    );
    w.insert_collider(ColliderDesc::sphere(0.1), off);
    run(&mut w, 60);
    let v_half = w.body(half).unwrap().linvel().y;
    let v_off = w.body(off).unwrap().linvel().y;
    assert!(
        (v_half + 0.5 * G).abs() < 1e-3,
        "scaled gravity: vy {v_half}, expected {}",
        -0.5 * G
    );
    assert!(v_off.abs() < 1e-6, "gravity off: vy {v_off}, expected 0");
}

#[test]
fn force_is_accumulated_then_cleared_after_step() {
    let s = PhysicsSettings {
        gravity: Vec3::ZERO,
        ..Default::default()
    };
    let mut w = PhysicsWorld::new(s);
    let b = w.insert_body(RigidBodyDesc::dynamic());
    w.insert_collider(ColliderDesc::sphere(0.5), b);
    let m = w.body(b).unwrap().mass();
    let expected_mass = 1000.0 * 4.0 / 3.0 * std::f32::consts::PI * 0.125;
    assert!(
        (m - expected_mass).abs() < 1e-2 * expected_mass,
        "mass {m}, expected {expected_mass}"
    );
    // Two forces of F/2 for one step: Δv = F·dt/m.
    let f = 600.0;
    w.body_mut(b).unwrap().add_force(Vec3::X * f * 0.5);
    w.body_mut(b).unwrap().add_force(Vec3::X * f * 0.5);
    w.step();
    let v1 = w.body(b).unwrap().linvel().x;
    let expected = f / 60.0 / m;
    assert!(
        (v1 - expected).abs() < 1e-4,
        "Δv after one step: {v1}, expected {expected}"
    );
    assert_eq!(
        w.body(b).unwrap().user_force(),
        Vec3::ZERO,
        "force must be cleared after the step"
    );
    w.step();
    let v2 = w.body(b).unwrap().linvel().x;
    assert!(
        (v2 - v1).abs() < 1e-6,
        "no force in second step: v {v2}, expected {v1}"
    );
}

#[test]
fn linear_damping_decays_velocity_exponentially() {
    let s = PhysicsSettings {
        gravity: Vec3::ZERO,
        ..Default::default()
    };
    let mut w = PhysicsWorld::new(s);
    let d = 0.5;
    let b = w.insert_body(
        RigidBodyDesc::dynamic()
            .linvel(Vec3::X * 10.0)
            .linear_damping(d)
            .can_sleep(false),
    );
    w.insert_collider(ColliderDesc::sphere(0.5), b);
    run(&mut w, 120); // 2 s
    let v = w.body(b).unwrap().linvel().x;
    let expected = 10.0 * (-d * 2.0f32).exp();
    assert!(
        (v - expected).abs() < 0.01 * expected,
        "damped v: {v}, expected {expected} ± 1%"
    );
}

#[test]
fn torque_free_spinning_box_keeps_angular_momentum() {
    let s = PhysicsSettings {
        gravity: Vec3::ZERO,
        ..Default::default()
    };
    let mut w = PhysicsWorld::new(s);
    let w0 = Vec3::new(1.0, 2.0, 3.0);
    let b = w.insert_body(RigidBodyDesc::dynamic().angvel(w0).can_sleep(false));
    w.insert_collider(ColliderDesc::cuboid(0.5, 1.0, 1.5), b);
    let l_of = |w: &PhysicsWorld| {
        let body = w.body(b).unwrap();
        body.world_inertia() * body.angvel()
    };
    let l0 = l_of(&w);
    let mut max_err = 0.0f32;
    for _ in 0..600 {
        w.step();
        max_err = max_err.max((l_of(&w) - l0).length() / l0.length());
    }
    let body = w.body(b).unwrap();
    // The motion is not a fixed-axis spin: the angular velocity must have changed direction.
    let turned = body.angvel().normalize().dot(w0.normalize());
    assert!(
        turned < 0.999,
        "angular velocity should precess (cos {turned})"
    );
    assert!(
        max_err < 0.01,
        "relative change of L over 10 s: {max_err}, expected < 1%"
    );
    let _ = Mat3::IDENTITY;
}

#[test]
fn axis_locks_hold_under_contact_and_force() {
    let (mut w, _) = world_with_ground(0.5);
    // A tilted static ramp that would push the box sideways and spin it.
    let ramp = w.insert_body(RigidBodyDesc::fixed().rotation(Quat::from_rotation_z(0.4)));
    w.insert_collider(ColliderDesc::cuboid(3.0, 0.2, 3.0), ramp);
    let b = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(0.3, 2.0, 0.2))
            .rotation(Quat::from_rotation_y(0.3))
            .locked_axes(
                LockedAxes::TRANSLATION_X | LockedAxes::TRANSLATION_Z | LockedAxes::ALL_ROTATIONS,
            ),
    );
    w.insert_collider(ColliderDesc::cuboid(0.3, 0.3, 0.3), b);
    let q0 = w.body(b).unwrap().rotation();
    for _ in 0..180 {
        w.body_mut(b)
            .unwrap()
            .add_force(Vec3::new(500.0, 0.0, -300.0));
        w.body_mut(b)
            .unwrap()
            .add_torque(Vec3::new(50.0, 20.0, 10.0));
        w.step();
    }
    let body = w.body(b).unwrap();
    let p = body.translation();
    assert!(
        (p.x - 0.3).abs() < 1e-4 && (p.z - 0.2).abs() < 1e-4,
        "locked x/z moved: {p}, expected x=0.3 z=0.2"
    );
    let dq = body.rotation().angle_between(q0);
    assert!(dq < 1e-4, "locked rotation turned by {dq} rad, expected 0");
    assert!(
        p.y < 2.0 - 0.5,
        "free y axis should still fall: y = {}",
        p.y
    );
}

#[test]
fn explicit_mass_overrides_density() {
    let s = PhysicsSettings {
        gravity: Vec3::ZERO,
        ..Default::default()
    };
    let mut w = PhysicsWorld::new(s);
    let mp = onyx_physics::MassProperties::new(Vec3::ZERO, 2.0, Vec3::splat(0.5));
    let b = w.insert_body(RigidBodyDesc::dynamic().mass_properties(mp));
    w.insert_collider(ColliderDesc::cuboid(1.0, 1.0, 1.0), b);
    assert_eq!(w.body(b).unwrap().mass(), 2.0);
    w.body_mut(b).unwrap().add_force(Vec3::Y * 120.0);
    w.body_mut(b).unwrap().add_torque(Vec3::Z * 30.0);
    w.step();
    let body = w.body(b).unwrap();
    // Δv = F·dt/m = 120/60/2 = 1; Δω = τ·dt/I = 30/60/0.5 = 1.
    assert!(
        (body.linvel().y - 1.0).abs() < 1e-5,
        "Δv {}, expected 1",
        body.linvel().y
    );
    assert!(
        (body.angvel().z - 1.0).abs() < 1e-5,
        "Δω {}, expected 1",
        body.angvel().z
    );
}
