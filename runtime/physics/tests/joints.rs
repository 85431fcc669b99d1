//! Joints against physics: pendulum periods (exact, any amplitude), a hinge motor's spin-up
//! `τ/I` and its target speed, a slider resting on its limit with the weight as reaction, a
//! rope that is slack until taut, a weld that holds a cantilever, a ball joint's cone, break
//! thresholds, collision filtering between jointed bodies, sleeping together.
mod common;
use common::*;
use onyx_physics::glam::{Quat, Vec3};
use onyx_physics::{
    BodyHandle, ColliderDesc, JointDesc, JointError, PhysicsPreset, PhysicsSettings, PhysicsWorld,
    RigidBodyDesc,
};

fn settings(p: PhysicsPreset) -> PhysicsSettings {
    PhysicsSettings {
        sleep_enabled: false,
        ..p.settings()
    }
}

/// The exact period of a simple pendulum of length `l` released from `theta0` (radians):
/// `T = 4 √(l/g) K(sin(θ₀/2))`, with the complete elliptic integral of the first kind by
/// the arithmetic–geometric mean.
fn exact_period(l: f64, theta0: f64) -> f64 {
    let k = (theta0 / 2.0).sin();
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    for _ in 0..30 {
        let (an, bn) = ((a + b) / 2.0, (a * b).sqrt());
        a = an;
        b = bn;
    }
    let big_k = std::f64::consts::PI / (2.0 * a);
    4.0 * (l / f64::from(G)).sqrt() * big_k
}

/// A bob of radius 1 cm on a massless rod of length `l` from a pivot at the origin, released
/// at `theta0` from straight down; returns the measured period (mean of the full swings over
/// `swings` periods, from the times the bob crosses the bottom moving the same way).
fn pendulum_period(p: PhysicsPreset, joint: JointDesc, l: f32, theta0: f32, swings: usize) -> f64 {
    let s = settings(p);
    let mut w = PhysicsWorld::new(s);
    let start = Vec3::new(l * theta0.sin(), -l * theta0.cos(), 0.0);
    let bob = w.insert_body(RigidBodyDesc::dynamic().translation(start));
    w.insert_collider(ColliderDesc::sphere(0.01), bob);
    // A rod holds the bob by its centre; a ball joint at the pivot (in the bob's frame).
    let rod = matches!(joint.kind, onyx_physics::JointKind::Distance { .. });
    let anchor_b = if rod { Vec3::ZERO } else { -start };
    w.insert_joint(
        joint.local_anchor_a(Vec3::ZERO).local_anchor_b(anchor_b),
        None,
        bob,
    )
    .unwrap();
    let mut crossings = Vec::new();
    let mut prev_x = start.x;
    let mut t = 0.0f64;
    let dt = f64::from(s.dt);
    while crossings.len() < swings + 1 && t < 100.0 {
        w.step();
        t += dt;
        let x = w.body(bob).unwrap().translation().x;
        if prev_x > 0.0 && x <= 0.0 {
            // Linear interpolation of the crossing time.
            let f = f64::from(prev_x / (prev_x - x));
            crossings.push(t - dt + f * dt);
        }
        prev_x = x;
    }
    assert!(crossings.len() > swings, "the pendulum stopped swinging");
    (crossings[swings] - crossings[0]) / swings as f64
}

#[test]
fn a_pendulum_swings_at_the_exact_period_for_small_and_large_amplitudes() {
    let l = 1.0f32;
    for preset in [PhysicsPreset::Balanced, PhysicsPreset::Precise] {
        for theta0 in [0.1f32, 1.0, 2.5] {
            let expected = exact_period(f64::from(l), f64::from(theta0));
            for (name, joint) in [
                ("rod", JointDesc::distance(l)),
                ("ball joint", JointDesc::spherical()),
            ] {
                let measured = pendulum_period(preset, joint, l, theta0, 5);
                let error = (measured - expected).abs() / expected;
                println!(
                    "{preset} {name} θ0 = {theta0}: period {measured:.5} s, exact {expected:.5} s \
                     ({:.3} %)",
                    100.0 * error
                );
                // Semi-implicit Euler with a soft joint: within 0.1 % of the exact period up
                // to 1 rad. Released nearly upside down (2.5 rad) the ball joint, whose bob
                // hangs 1 m from a 1 cm sphere's centre (a lever 100× its radius), loses a
                // little amplitude each swing and its period shortens: measured 0.54 % short
                // at balanced, 0.28 % at precise (the rod: 0.13 %, 0.08 %).
                let bound = if theta0 > 2.0 { 0.008 } else { 0.001 };
                assert!(
                    error < bound,
                    "{preset} {name} θ0 = {theta0}: period {measured} s, exact {expected} s"
                );
            }
        }
    }
}

#[test]
fn a_rod_keeps_its_length_while_swinging() {
    let s = settings(PhysicsPreset::Balanced);
    let mut w = PhysicsWorld::new(s);
    let start = Vec3::new(2.0, 0.0, 0.0);
    let bob = w.insert_body(RigidBodyDesc::dynamic().translation(start));
    w.insert_collider(ColliderDesc::sphere(0.05), bob);
    w.insert_joint(
        JointDesc::distance(2.0).local_anchor_a(Vec3::ZERO),
        None,
        bob,
    )
    .unwrap();
    let mut worst = 0.0f32;
    for _ in 0..600 {
        w.step();
        let r = w.body(bob).unwrap().translation().length();
        worst = worst.max((r - 2.0).abs());
    }
    println!("rod length error: worst {worst} m over 10 s (expected < 1 mm)");
    assert!(worst < 1e-3, "the rod stretched by {worst} m");
}

/// A wheel (a box 0.4 m × 0.4 m × 0.1 m, free to turn about Z on a hinge to the world).
fn wheel(w: &mut PhysicsWorld, joint: JointDesc) -> (BodyHandle, onyx_physics::JointHandle, f32) {
    let body = w.insert_body(RigidBodyDesc::dynamic());
    w.insert_collider(ColliderDesc::cuboid(0.2, 0.2, 0.05).density(500.0), body);
    let inertia = w.body(body).unwrap().mass_properties().inertia.z_axis.z;
    let j = w.insert_joint(joint, None, body).unwrap();
    (body, j, inertia)
}

#[test]
fn a_hinge_motor_spins_up_at_torque_over_inertia_and_holds_its_target_speed() {
    for preset in PhysicsPreset::ALL {
        let s = PhysicsSettings {
            gravity: Vec3::ZERO,
            ..settings(preset)
        };
        let mut w = PhysicsWorld::new(s);
        let (target, torque) = (6.0f32, 0.5f32);
        let (body, _, inertia) = wheel(
            &mut w,
            JointDesc::revolute(Vec3::Z).motor_velocity(target, torque),
        );
        // Spin-up: ω(t) = τ t / I while below the target.
        let spin_up = target * inertia / torque;
        let t = 0.5 * spin_up;
        let steps = (t / s.dt).round() as usize;
        run(&mut w, steps);
        let omega = w.body(body).unwrap().angvel().z;
        let expected = torque * steps as f32 * s.dt / inertia;
        println!("{preset}: ω after {t:.3} s = {omega:.4} rad/s, τt/I = {expected:.4}");
        assert!(
            (omega - expected).abs() < 0.01 * expected,
            "{preset}: spin-up ω = {omega}, expected τt/I = {expected}"
        );
        run(&mut w, steps * 2);
        let omega = w.body(body).unwrap().angvel();
        println!("{preset}: ω at the end = {omega:?} (target {target})");
        assert!(
            (omega.z - target).abs() < 1e-3 * target
                && omega.x.abs() < 1e-4
                && omega.y.abs() < 1e-4,
            "{preset}: motor holds ω = {omega:?}, target {target} about Z"
        );
    }
}

#[test]
fn a_position_motor_turns_a_hinge_to_its_angle_and_limits_stop_it() {
    let s = PhysicsSettings {
        gravity: Vec3::ZERO,
        ..settings(PhysicsPreset::Balanced)
    };
    let mut w = PhysicsWorld::new(s);
    let (_, servo, _) = wheel(
        &mut w,
        JointDesc::revolute(Vec3::Z).motor_position(1.2, 4.0, 1.0, 100.0),
    );
    run(&mut w, 240);
    let angle = w.joint_coordinate(servo).unwrap();
    println!("servo angle after 4 s: {angle} rad (target 1.2)");
    assert!(
        (angle - 1.2).abs() < 0.01,
        "servo at {angle} rad, target 1.2"
    );

    // A motor pushing past an upper limit of 0.5 rad stops at it.
    let mut w = PhysicsWorld::new(s);
    let (_, limited, _) = wheel(
        &mut w,
        JointDesc::revolute(Vec3::Z)
            .limits(-0.25, 0.5)
            .motor_velocity(3.0, 5.0),
    );
    run(&mut w, 120);
    let angle = w.joint_coordinate(limited).unwrap();
    println!("motor against a 0.5 rad limit: at {angle} rad");
    assert!((angle - 0.5).abs() < 0.01, "at {angle} rad, limit 0.5");
}

#[test]
fn a_slider_rests_on_its_limit_carrying_the_weight() {
    for preset in PhysicsPreset::ALL {
        let s = settings(preset);
        let mut w = PhysicsWorld::new(s);
        let body = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, 1.0, 0.0)));
        w.insert_collider(ColliderDesc::cuboid(0.1, 0.1, 0.1).density(1000.0), body);
        let m = w.body(body).unwrap().mass();
        // A vertical slider from (0, 1, 0): the body may drop 0.3 m, then the limit holds it.
        let j = w
            .insert_joint(
                JointDesc::prismatic(Vec3::Y)
                    .local_anchor_a(Vec3::new(0.0, 1.0, 0.0))
                    .limits(-0.3, 0.3),
                None,
                body,
            )
            .unwrap();
        run(&mut w, (2.0 / s.dt) as usize);
        let x = w.joint_coordinate(j).unwrap();
        let p = w.body(body).unwrap().translation();
        let force = w.joint(j).unwrap().reaction_force();
        println!(
            "{preset}: slider at {x:.5} m (limit −0.3), body at {p:?}, force {force:?}, mg = {}",
            m * G
        );
        assert!(
            (x + 0.3).abs() < 2e-3,
            "{preset}: rests at {x} m, limit −0.3"
        );
        assert!(
            p.x.abs() < 1e-4 && p.z.abs() < 1e-4,
            "{preset}: left its axis: {p:?}"
        );
        assert!(
            (force.y - m * G).abs() < 0.01 * m * G,
            "{preset}: reaction {force:?}, weight {}",
            m * G
        );
    }
}

#[test]
fn a_rope_is_slack_until_taut() {
    let s = settings(PhysicsPreset::Balanced);
    let mut w = PhysicsWorld::new(s);
    let body = w.insert_body(RigidBodyDesc::dynamic());
    w.insert_collider(ColliderDesc::sphere(0.05), body);
    w.insert_joint(JointDesc::rope(1.0).local_anchor_a(Vec3::ZERO), None, body)
        .unwrap();
    // Free fall while slack: y = −g t²/2 until 1 m below the anchor (t = √(2/g) = 0.4515 s).
    run(&mut w, 24);
    let y = w.body(body).unwrap().translation().y;
    let t = 24.0 * s.dt;
    let free = -0.5 * G * t * t;
    println!("after {t} s: y = {y}, free fall says {free}");
    assert!(
        (y - free).abs() < 0.03,
        "the slack rope held it: y = {y}, free fall {free}"
    );
    run(&mut w, 240);
    let y = w.body(body).unwrap().translation().y;
    println!("after the rope went taut: y = {y} (rope 1 m)");
    assert!(
        (y + 1.0).abs() < 5e-3 && y > -1.005,
        "hangs at {y}, rope 1 m"
    );
}

#[test]
fn a_weld_holds_a_cantilever_with_the_moment_of_its_weight() {
    let s = settings(PhysicsPreset::Balanced);
    let mut w = PhysicsWorld::new(s);
    // A 1 m beam welded at its left end to the world, centre 0.5 m out.
    let beam = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.5, 2.0, 0.0)));
    w.insert_collider(ColliderDesc::cuboid(0.5, 0.05, 0.05), beam);
    let m = w.body(beam).unwrap().mass();
    let j = w
        .insert_joint(
            JointDesc::fixed()
                .local_anchor_a(Vec3::new(0.0, 2.0, 0.0))
                .local_anchor_b(Vec3::new(-0.5, 0.0, 0.0)),
            None,
            beam,
        )
        .unwrap();
    run(&mut w, 300);
    let b = w.body(beam).unwrap();
    let (axis, angle) = b.rotation().to_axis_angle();
    let sag = 2.0 - b.translation().y;
    let joint = w.joint(j).unwrap();
    println!(
        "cantilever: sag {sag} m, tilt {angle} rad about {axis:?}, force {:?}, torque {:?}",
        joint.reaction_force(),
        joint.reaction_torque()
    );
    assert!(
        sag.abs() < 1e-3 && angle < 2e-3,
        "sagged {sag} m, tilted {angle} rad"
    );
    assert!((joint.reaction_force().y - m * G).abs() < 0.01 * m * G);
    // The weld's torque on the beam balances its weight's moment about the anchor:
    // m g · 0.5 m, about +Z (the weight turns it clockwise, about −Z).
    let torque = joint.reaction_torque().z;
    assert!(
        (torque - 0.5 * m * G).abs() < 0.02 * m * G,
        "weld torque {torque}, expected m g · 0.5 = {}",
        0.5 * m * G
    );
}

#[test]
fn a_ball_joint_keeps_its_swing_inside_the_cone() {
    let s = settings(PhysicsPreset::Balanced);
    let mut w = PhysicsWorld::new(s);
    // A rod hanging along −Y from the origin, its joint axis along −Y on both sides, kicked
    // sideways hard.
    let rod = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(0.0, -0.5, 0.0))
            .linvel(Vec3::new(6.0, 0.0, 2.0)),
    );
    w.insert_collider(ColliderDesc::cuboid(0.05, 0.5, 0.05), rod);
    let cone = 0.4f32;
    w.insert_joint(
        JointDesc::spherical()
            .local_axis_a(-Vec3::Y)
            .local_axis_b(-Vec3::Y)
            .local_anchor_b(Vec3::new(0.0, 0.5, 0.0))
            .cone_limit(cone),
        None,
        rod,
    )
    .unwrap();
    let mut widest = 0.0f32;
    for _ in 0..300 {
        w.step();
        let axis = w.body(rod).unwrap().rotation() * -Vec3::Y;
        widest = widest.max(axis.angle_between(-Vec3::Y));
    }
    println!("widest swing {widest} rad, cone {cone}");
    assert!(widest < cone + 0.02, "swung to {widest} rad, cone {cone}");
    assert!(
        widest > cone - 0.05,
        "the kick should reach the cone: {widest}"
    );
}

#[test]
fn a_joint_breaks_once_past_its_force_and_holds_below_it() {
    for (threshold, breaks) in [(0.9f32, true), (1.2, false)] {
        let s = settings(PhysicsPreset::Balanced);
        let mut w = PhysicsWorld::new(s);
        let body = w.insert_body(RigidBodyDesc::dynamic());
        w.insert_collider(ColliderDesc::sphere(0.1), body);
        let weight = w.body(body).unwrap().mass() * G;
        let j = w
            .insert_joint(
                JointDesc::spherical().break_force(threshold * weight),
                None,
                body,
            )
            .unwrap();
        let mut reports = Vec::new();
        for _ in 0..120 {
            reports.extend(w.step().broken_joints.iter().map(|b| (b.joint, b.force)));
        }
        let y = w.body(body).unwrap().translation().y;
        println!("break at {threshold}× the weight: reports {reports:?}, y = {y}");
        if breaks {
            assert_eq!(reports.len(), 1, "reported once: {reports:?}");
            assert_eq!(reports[0].0, j);
            assert!(w.joint(j).unwrap().is_broken());
            assert!(y < -0.5, "a broken joint still held the body at {y}");
        } else {
            assert!(reports.is_empty(), "{reports:?}");
            assert!(y.abs() < 1e-3, "held at {y}");
        }
    }
}

#[test]
fn jointed_bodies_do_not_collide_unless_the_joint_says_so() {
    for collide in [false, true] {
        let mut w = PhysicsWorld::new(PhysicsSettings {
            gravity: Vec3::ZERO,
            ..settings(PhysicsPreset::Balanced)
        });
        // Two overlapping boxes on a hinge: without collisions they stay overlapped and
        // still; with them, they are pushed apart.
        let a = w.insert_body(RigidBodyDesc::dynamic());
        w.insert_collider(ColliderDesc::cuboid(0.5, 0.5, 0.5), a);
        let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.8, 0.0, 0.0)));
        w.insert_collider(ColliderDesc::cuboid(0.5, 0.5, 0.5), b);
        w.insert_joint(
            JointDesc::spherical()
                .local_anchor_a(Vec3::new(0.4, 0.0, 0.0))
                .local_anchor_b(Vec3::new(-0.4, 0.0, 0.0))
                .collide_connected(collide),
            Some(a),
            b,
        )
        .unwrap();
        run(&mut w, 60);
        let contacts = w
            .narrowphase()
            .pairs()
            .iter()
            .filter(|p| p.touching)
            .count();
        let spin = w.body(a).unwrap().angvel().length() + w.body(b).unwrap().angvel().length();
        println!("collide_connected {collide}: {contacts} touching pairs, spin {spin}");
        if collide {
            assert_eq!(contacts, 1);
        } else {
            assert_eq!(contacts, 0);
            assert!(spin < 1e-4, "nothing acts, yet they turn: {spin}");
        }
    }
}

#[test]
fn a_chain_at_rest_falls_asleep_together_and_wakes_together() {
    let s = PhysicsPreset::Balanced.settings();
    let mut w = PhysicsWorld::new(s);
    let mut links = Vec::new();
    let mut prev: Option<BodyHandle> = None;
    for i in 0..5 {
        let y = -0.5 - i as f32;
        let link = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, y, 0.0)));
        w.insert_collider(ColliderDesc::cuboid(0.05, 0.5, 0.05), link);
        let anchor_a = if prev.is_some() {
            Vec3::new(0.0, -0.5, 0.0)
        } else {
            Vec3::ZERO
        };
        w.insert_joint(
            JointDesc::spherical()
                .local_anchor_a(anchor_a)
                .local_anchor_b(Vec3::new(0.0, 0.5, 0.0)),
            prev,
            link,
        )
        .unwrap();
        links.push(link);
        prev = Some(link);
    }
    run(&mut w, 180);
    assert!(
        links.iter().all(|&l| w.body(l).unwrap().is_sleeping()),
        "a hanging chain at rest sleeps"
    );
    // Pushing the bottom link wakes the whole chain.
    w.body_mut(links[4]).unwrap().apply_impulse(Vec3::X);
    w.step();
    let awake = links
        .iter()
        .filter(|&&l| !w.body(l).unwrap().is_sleeping())
        .count();
    assert_eq!(awake, 5, "only {awake} of 5 links woke");
    let top = w.body(links[0]).unwrap().linvel().length();
    assert!(top > 0.0, "the top link did not feel the push");
}

#[test]
fn bad_joints_are_refused_with_the_field_named() {
    let mut w = PhysicsWorld::default();
    let a = w.insert_body(RigidBodyDesc::dynamic());
    let gone = w.insert_body(RigidBodyDesc::dynamic());
    w.remove_body(gone);
    let cases: [(JointDesc, &str); 6] = [
        (JointDesc::revolute(Vec3::ZERO), "frame_a"),
        (JointDesc::revolute(Vec3::Z).limits(1.0, -1.0), "limits"),
        (JointDesc::revolute(Vec3::Z).limits(-4.0, 0.0), "limits"),
        (
            JointDesc::prismatic(Vec3::X).motor_velocity(f32::NAN, 1.0),
            "motor.target",
        ),
        (JointDesc::distance(-1.0), "limits"),
        (
            JointDesc::spherical().local_anchor_b(Vec3::new(f32::INFINITY, 0.0, 0.0)),
            "frame_b",
        ),
    ];
    for (desc, field) in cases {
        match w.insert_joint(desc, None, a) {
            Err(JointError::Invalid { field: f, message }) => {
                assert_eq!(f, field, "{message}");
            }
            other => panic!("expected {field} refused, got {other:?}"),
        }
    }
    assert_eq!(
        w.insert_joint(JointDesc::fixed(), Some(gone), a)
            .unwrap_err(),
        JointError::NoSuchBody(gone)
    );
    assert_eq!(
        w.insert_joint(JointDesc::fixed(), Some(a), a).unwrap_err(),
        JointError::SameBody(a)
    );
    assert!(w.joints().is_empty());
}

#[test]
fn joints_far_from_the_origin_hold_as_at_the_origin() {
    // Relative geometry: a pendulum 1e4 m out swings like one at the origin.
    let s = settings(PhysicsPreset::Balanced);
    let swing = |origin: Vec3| {
        let mut w = PhysicsWorld::new(s);
        let bob = w.insert_body(
            RigidBodyDesc::dynamic()
                .translation(origin + Vec3::new(1.0, 0.0, 0.0))
                .rotation(Quat::IDENTITY),
        );
        w.insert_collider(ColliderDesc::sphere(0.05), bob);
        w.insert_joint(
            JointDesc::revolute(Vec3::Z)
                .local_anchor_a(origin)
                .local_anchor_b(Vec3::new(-1.0, 0.0, 0.0)),
            None,
            bob,
        )
        .unwrap();
        run(&mut w, 120);
        w.body(bob).unwrap().translation() - origin
    };
    let near = swing(Vec3::ZERO);
    let far = swing(Vec3::new(1.0e4, 0.0, -1.0e4));
    println!("after 2 s: near {near:?}, far {far:?}");
    // Two f32 position quanta at 1e4 m (≈ 1 mm each).
    assert!((near - far).length() < 4e-3, "near {near:?}, far {far:?}");
}
