//! Resting contacts under heavy loads and on small bodies: a heavy box on a light one, and
//! penetration relative to size (1 mm … 1 km), against the ideal of no sinking.
//!
//! A 1000 kg box on a 1 kg box fell through it at fast and balanced and sank 13 cm at
//! precise; a 1 mm ball on a box sank 24 % of its size at balanced: contacts settled at a
//! fixed depth per load, not relative to the bodies' size, and Gauss–Seidel needed about
//! `√ratio` substeps to catch a heavy body.
mod common;
use common::*;
use onyx_physics::glam::Vec3;
use onyx_physics::RigidBodyDesc;
use onyx_physics::{BodyHandle, ColliderDesc, PhysicsPreset, PhysicsSettings, PhysicsWorld};

fn settings(p: PhysicsPreset) -> PhysicsSettings {
    PhysicsSettings {
        sleep_enabled: false,
        ..p.settings()
    }
}

/// A cube of half size `heavy_half`, `ratio` times heavier than the cube of half size
/// `light_half` it rests on, on a static ground box, every collider of the default material.
/// Returns the world, the light and the heavy cube, and where the heavy cube's centre starts
/// (its height, m).
fn heavy_on_light_world(
    p: PhysicsPreset,
    ratio: f32,
    light_half: f32,
    heavy_half: f32,
) -> (PhysicsWorld, BodyHandle, BodyHandle, f32) {
    let mut w = PhysicsWorld::new(settings(p));
    let ground = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(
        ColliderDesc::cuboid(20.0, 0.5, 20.0).translation(Vec3::Y * -0.5),
        ground,
    );
    let light = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::Y * light_half));
    w.insert_collider(
        ColliderDesc::cuboid(light_half, light_half, light_half).density(1000.0),
        light,
    );
    let m_light = w.body(light).unwrap().mass();
    let y0 = 2.0 * light_half + heavy_half;
    let heavy = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::Y * y0));
    let volume = (2.0 * heavy_half).powi(3);
    w.insert_collider(
        ColliderDesc::cuboid(heavy_half, heavy_half, heavy_half).density(ratio * m_light / volume),
        heavy,
    );
    (w, light, heavy, y0)
}

/// [`heavy_on_light_world`] run for 5 s. Returns how far the heavy cube sank from where it
/// was placed (worst over the run, and at the end), metres.
fn heavy_on_light(p: PhysicsPreset, ratio: f32, light_half: f32, heavy_half: f32) -> (f32, f32) {
    let (mut w, _, heavy, y0) = heavy_on_light_world(p, ratio, light_half, heavy_half);
    let mut worst = 0.0f32;
    for _ in 0..(5.0 / w.settings().dt) as usize {
        w.step();
        worst = worst.max(y0 - w.body(heavy).unwrap().translation().y);
    }
    (worst, y0 - w.body(heavy).unwrap().translation().y)
}

#[test]
fn a_heavy_box_on_a_light_box_barely_sinks() {
    // The targets: < 1 cm at precise, < 2 cm at balanced, for ratios up to 1000:1.
    for (preset, limit) in [
        (PhysicsPreset::Balanced, 0.02),
        (PhysicsPreset::Precise, 0.01),
    ] {
        for (light_half, heavy_half) in [(0.5f32, 0.5f32), (0.05, 0.5), (0.5, 0.05)] {
            for ratio in [1.0f32, 10.0, 100.0, 400.0, 1000.0] {
                let (worst, end) = heavy_on_light(preset, ratio, light_half, heavy_half);
                println!(
                    "{preset} {ratio}:1, cubes {} m on {} m: sank {end:.4} m (worst {worst:.4}), \
                     expected < {limit}",
                    2.0 * heavy_half,
                    2.0 * light_half
                );
                assert!(
                    worst < limit && end.abs() < limit,
                    "{preset}: a {ratio}:1 box sank {worst} m (end {end}), expected < {limit}"
                );
            }
        }
    }
}

/// What the small bodies rest on.
#[derive(Clone, Copy, Debug)]
enum Ground {
    HalfSpace,
    /// A static box 40 km wide (its top at y = 0), as a scene with 1 km bodies needs.
    WideBox,
}

/// A ball of radius `r` resting on a dynamic box resting on the ground, for 10 s. Returns the
/// ball's penetration into the box and how far it moved sideways on it, both as fractions of
/// its diameter.
fn ball_on_box(p: PhysicsPreset, r: f32, ground: Ground) -> (f32, f32) {
    let s = settings(p);
    let mut w = PhysicsWorld::new(s);
    let g = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(
        match ground {
            Ground::HalfSpace => ColliderDesc::half_space(Vec3::Y),
            Ground::WideBox => {
                ColliderDesc::cuboid(20_000.0, 0.5, 20_000.0).translation(Vec3::Y * -0.5)
            }
        },
        g,
    );
    let half = 2.0 * r;
    let x = 1.0 + 4.0 * r;
    let bx = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(x, half, 0.0)));
    w.insert_collider(ColliderDesc::cuboid(4.0 * r, half, 4.0 * r), bx);
    let start = Vec3::new(x, 2.0 * half + r, 0.0);
    let ball: BodyHandle = w.insert_body(RigidBodyDesc::dynamic().translation(start));
    w.insert_collider(ColliderDesc::sphere(r), ball);
    run(&mut w, (10.0 / s.dt) as usize);
    let top = w.body(bx).unwrap().translation().y + half;
    let at = w.body(ball).unwrap().translation();
    let sideways = Vec3::new(at.x - start.x, 0.0, at.z - start.z).length();
    ((top + r - at.y) / (2.0 * r), sideways / (2.0 * r))
}

/// A ball rests on a box at most 5 % of its size deep and stays where it was put, from 1 mm
/// to 1 km. A contact point kept on a ball from one step to the next turned with it as it
/// rolled, and the normal force on the turned point turned it further: a 1 mm ball rolled
/// off its box within 3 s (its box on a wide ground box at precise).
#[test]
fn resting_penetration_is_a_few_percent_of_size_from_1_mm_to_1_km() {
    for preset in [PhysicsPreset::Balanced, PhysicsPreset::Precise] {
        for ground in [Ground::HalfSpace, Ground::WideBox] {
            for diameter in [0.001f32, 0.01, 0.1, 1.0, 10.0, 100.0, 1000.0] {
                let (pen, sideways) = ball_on_box(preset, 0.5 * diameter, ground);
                println!(
                    "{preset} {ground:?} ball {diameter} m: penetration {pen:.4} of its size \
                     (expected ≤ 0.05), moved {sideways:.2e} of its size"
                );
                assert!(
                    (0.0..=0.05).contains(&pen),
                    "{preset} {ground:?}: a {diameter} m ball rests {pen} of its size deep, \
                     expected 0 … 5 %"
                );
                assert!(
                    sideways < 0.01,
                    "{preset} {ground:?}: a {diameter} m ball resting on a box moved {sideways} \
                     of its size sideways in 10 s, expected < 1 %"
                );
            }
        }
    }
}

#[test]
fn a_contact_the_step_cannot_hold_is_reported_once_with_the_preset_that_would() {
    // A 1 mm ball on a box at `fast`: the stiffest contact a 30 Hz step allows deflects it
    // about g / ω², several times its 2 % budget.
    let r = 0.0005;
    let s = settings(PhysicsPreset::Fast);
    let mut w = PhysicsWorld::new(s);
    let ground = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(ColliderDesc::half_space(Vec3::Y), ground);
    let bx = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::Y * 2.0 * r));
    w.insert_collider(ColliderDesc::cuboid(4.0 * r, 2.0 * r, 4.0 * r), bx);
    let ball = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::Y * 5.0 * r));
    w.insert_collider(ColliderDesc::sphere(r), ball);
    let mut reports = Vec::new();
    for _ in 0..(3.0 / s.dt) as usize {
        reports.extend(w.step().overloaded_contacts.iter().copied());
    }
    let top = w.body(bx).unwrap().translation().y + 2.0 * r;
    let measured = top + r - w.body(ball).unwrap().translation().y;
    println!("reports: {reports:?}; measured depth {measured} m");
    let mine: Vec<_> = reports
        .iter()
        .filter(|o| [o.body_a, o.body_b] == [bx, ball] || [o.body_a, o.body_b] == [ball, bx])
        .collect();
    assert_eq!(
        mine.len(),
        1,
        "expected the ball's contact reported once: {reports:?}"
    );
    let o = mine[0];
    assert_eq!(o.holding_preset, Some(PhysicsPreset::Precise));
    assert!(
        (o.expected_depth - measured).abs() < 0.3 * measured,
        "reported depth {} m, measured {measured} m (expected within 30 %)",
        o.expected_depth
    );
    assert!((o.allowed_depth - 0.02 * 2.0 * r).abs() < 1e-9);
    assert!(o.load_ratio >= 1.0, "load ratio {}", o.load_ratio);
    let m = w.body(bx).unwrap().mass() / w.body(ball).unwrap().mass();
    assert!(o.mass_ratio.is_some_and(|x| (x - m).abs() < 1e-3 * m));
}

#[test]
fn bodies_moving_past_the_precise_range_are_named_once() {
    let s = PhysicsSettings {
        gravity: Vec3::ZERO,
        ..settings(PhysicsPreset::Balanced)
    };
    let range = s.precise_range();
    assert_eq!(range, 16_384.0, "1 mm spacing holds to 2^14 m");
    let mut w = PhysicsWorld::new(s);
    let near = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::X * 0.9 * range)
            .linvel(Vec3::Y),
    );
    w.insert_collider(ColliderDesc::sphere(0.5), near);
    let far = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::Z * -1.1 * range)
            .linvel(Vec3::Y),
    );
    w.insert_collider(ColliderDesc::sphere(0.5), far);
    let first = w.step().far_bodies.clone();
    println!("far bodies: {first:?}");
    assert_eq!(first.len(), 1);
    assert_eq!(first[0].body, far);
    assert_eq!(first[0].range, range);
    for _ in 0..10 {
        assert!(w.step().far_bodies.is_empty(), "reported twice");
    }
}

#[test]
fn an_impact_is_not_reported_as_an_overloaded_contact() {
    // Bullets stopped by a 1 cm wall (CCD, no gravity, 300 and 1000 m/s) and balls thrown
    // down onto the ground at 20 m/s: the impact's impulse is no load the contact settles
    // under, and nothing rests on anything afterwards but a ball's own weight. Counted as
    // load, each impact was named overloaded ("carries 13387× its weight, no preset holds
    // it").
    for preset in PhysicsPreset::ALL {
        let s = settings(preset);
        let mut w = PhysicsWorld::new(s);
        let wall = w.insert_body(RigidBodyDesc::fixed().translation(Vec3::X * 10.0));
        w.insert_collider(ColliderDesc::cuboid(0.005, 50.0, 50.0), wall);
        let ground = w.insert_body(RigidBodyDesc::fixed());
        w.insert_collider(
            ColliderDesc::cuboid(5.0, 0.5, 5.0).translation(Vec3::new(-20.0, -0.5, 0.0)),
            ground,
        );
        for (i, speed) in [300.0f32, 1000.0].into_iter().enumerate() {
            let y = i as f32 * 2.0;
            let shapes = [
                ColliderDesc::sphere(0.05),
                ColliderDesc::cuboid(0.05, 0.05, 0.05),
            ];
            for (z, shape) in shapes.into_iter().enumerate() {
                let bullet = w.insert_body(
                    RigidBodyDesc::dynamic()
                        .translation(Vec3::new(0.0, y, z as f32))
                        .linvel(Vec3::X * speed)
                        .gravity_scale(0.0)
                        .ccd_enabled(true),
                );
                w.insert_collider(shape, bullet);
            }
        }
        for (i, r) in [0.05f32, 0.5].into_iter().enumerate() {
            let ball = w.insert_body(
                RigidBodyDesc::dynamic()
                    .translation(Vec3::new(-22.0 + 3.0 * i as f32, 2.0, 0.0))
                    .linvel(Vec3::Y * -20.0)
                    .ccd_enabled(true),
            );
            w.insert_collider(ColliderDesc::sphere(r), ball);
        }
        let mut reports = Vec::new();
        for _ in 0..(1.0 / s.dt) as usize {
            reports.extend(w.step().overloaded_contacts.iter().copied());
        }
        assert!(
            reports.is_empty(),
            "{preset}: impacts reported as overloaded contacts: {reports:?}"
        );
    }
}

/// A heavy box on a light one on the ground (40 cm cubes, [`heavy_on_light_world`]), the
/// light box pushed sideways with 30 % of the force the ground's sliding friction holds under
/// the pair's whole weight: it must not slide. Open (issue 15): the heavy-on-light mass
/// scaling (`support_mass_scale`) solves the light box as if it were
/// `max_support_mass_ratio` (10) times lighter than the heavy one, so its ground contact
/// carries about `(1 + 10)·m_light·g`, not the pair's weight, and the friction under it is as
/// much too weak: 100:1 slid 270 m in 2 s and 1000:1 1.6 km at every preset; 30:1 held at
/// balanced and precise (6 mm, 0.4 mm). At fast 9:1 to 30:1 slid 6 cm to 5.7 m as well,
/// below the scaling's threshold: one iteration a substep carries the heavy box's weight
/// down to the ground too slowly for its friction. Run with `--ignored` to see it.
#[test]
#[ignore = "open: the ground under a heavily loaded light body carries too little load for friction"]
fn a_light_box_under_a_heavy_one_holds_friction_for_the_pair() {
    let sliding_friction = onyx_physics::Material::default().dynamic_friction;
    for preset in PhysicsPreset::ALL {
        for ratio in [10.0f32, 100.0, 1000.0] {
            let (mut w, light, heavy, _) = heavy_on_light_world(preset, ratio, 0.2, 0.2);
            let total = w.body(light).unwrap().mass() + w.body(heavy).unwrap().mass();
            let push = 0.3 * sliding_friction * total * G;
            let settle = (0.5 / w.settings().dt) as usize;
            run(&mut w, settle);
            let x0 = w.body(light).unwrap().translation().x;
            for _ in 0..(2.0 / w.settings().dt) as usize {
                w.body_mut(light).unwrap().add_force(Vec3::X * push);
                w.step();
            }
            let slid = w.body(light).unwrap().translation().x - x0;
            assert!(
                slid.abs() < 0.01,
                "{preset}, {ratio}:1: pushed with 30 % of the pair's sliding friction, the \
                 light box slid {slid} m in 2 s"
            );
        }
    }
}
