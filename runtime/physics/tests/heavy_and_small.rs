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
use onyx_physics::{
    BodyHandle, ColliderDesc, Material, OverloadedContact, PhysicsPreset, PhysicsSettings,
    PhysicsWorld,
};

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
    heavy_on_light_world_of(p, ratio, light_half, heavy_half, Material::default())
}

/// [`heavy_on_light_world`] with every collider of `material`.
fn heavy_on_light_world_of(
    p: PhysicsPreset,
    ratio: f32,
    light_half: f32,
    heavy_half: f32,
    material: Material,
) -> (PhysicsWorld, BodyHandle, BodyHandle, f32) {
    let mut w = PhysicsWorld::new(settings(p));
    let ground = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(
        ColliderDesc::cuboid(20.0, 0.5, 20.0)
            .translation(Vec3::Y * -0.5)
            .material(material),
        ground,
    );
    let light = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::Y * light_half));
    w.insert_collider(
        ColliderDesc::cuboid(light_half, light_half, light_half)
            .density(1000.0)
            .material(material),
        light,
    );
    let m_light = w.body(light).unwrap().mass();
    let y0 = 2.0 * light_half + heavy_half;
    let heavy = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::Y * y0));
    let volume = (2.0 * heavy_half).powi(3);
    w.insert_collider(
        ColliderDesc::cuboid(heavy_half, heavy_half, heavy_half)
            .density(ratio * m_light / volume)
            .material(material),
        heavy,
    );
    (w, light, heavy, y0)
}

/// [`heavy_on_light_world`] with friction `friction` run for 5 s. Returns how far the heavy cube sank from where it
/// was placed (worst over the run, and at the end), metres.
fn heavy_on_light(
    p: PhysicsPreset,
    ratio: f32,
    light_half: f32,
    heavy_half: f32,
    friction: f32,
) -> (f32, f32) {
    let material = Material {
        static_friction: friction,
        dynamic_friction: friction,
        ..Material::default()
    };
    let (mut w, _, heavy, y0) = heavy_on_light_world_of(p, ratio, light_half, heavy_half, material);
    let mut worst = 0.0f32;
    for _ in 0..(5.0 / w.settings().dt) as usize {
        w.step();
        worst = worst.max(y0 - w.body(heavy).unwrap().translation().y);
    }
    (worst, y0 - w.body(heavy).unwrap().translation().y)
}

/// The targets: less than 1 cm at precise and 2 cm at balanced, for ratios up to
/// 1000:1, with friction and without. Frictionless, solved on the true masses as a plain
/// column, 1000:1 on 1 m cubes sank 4 cm (2 cm a face, the whole depth budget): a heavy
/// body's column is now stiffened for a share of it (`HEAVY_COLUMN_DEPTH_SHARE`; 6 mm).
#[test]
fn a_heavy_box_on_a_light_box_barely_sinks() {
    for (preset, limit) in [
        (PhysicsPreset::Balanced, 0.02),
        (PhysicsPreset::Precise, 0.01),
    ] {
        for (light_half, heavy_half) in [(0.5f32, 0.5f32), (0.05, 0.5), (0.5, 0.05)] {
            for (ratio, friction) in [1.0f32, 10.0, 100.0, 400.0, 1000.0]
                .into_iter()
                .flat_map(|r| [(r, Material::default().dynamic_friction), (r, 0.0)])
            {
                let (worst, end) = heavy_on_light(preset, ratio, light_half, heavy_half, friction);
                println!(
                    "{preset} {ratio}:1, friction {friction}, cubes {} m on {} m: sank {end:.4} \
                     m (worst {worst:.4}), expected < {limit}",
                    2.0 * heavy_half,
                    2.0 * light_half
                );
                assert!(
                    worst < limit && end.abs() < limit,
                    "{preset}: a {ratio}:1 box, friction {friction}, sank {worst} m (end {end}), \
                     expected < {limit}"
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

/// A box of half extents `half` resting on `ground` (the half-space, or a dynamic box twice
/// its width and its thickness on the half-space), for 10 s. Returns its penetration into
/// what it rests on as a fraction of its thickness (`2·half.y`), and how far it moved sideways
/// as one of its width.
fn thin_box_on(p: PhysicsPreset, half: Vec3, on_box: bool) -> (f32, f32) {
    let s = settings(p);
    let mut w = PhysicsWorld::new(s);
    let g = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(ColliderDesc::half_space(Vec3::Y), g);
    let support = on_box.then(|| {
        let support_half = Vec3::new(2.0 * half.x, half.y, 2.0 * half.z);
        let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::Y * support_half.y));
        w.insert_collider(
            ColliderDesc::cuboid(support_half.x, support_half.y, support_half.z),
            b,
        );
        (b, support_half.y)
    });
    let base = support.map_or(0.0, |(_, h)| 2.0 * h);
    let start = Vec3::new(0.0, base + half.y, 0.0);
    let b = w.insert_body(RigidBodyDesc::dynamic().translation(start));
    w.insert_collider(ColliderDesc::cuboid(half.x, half.y, half.z), b);
    run(&mut w, (10.0 / s.dt) as usize);
    let top = support.map_or(0.0, |(s, h)| w.body(s).unwrap().translation().y + h);
    let at = w.body(b).unwrap().translation();
    let sideways = Vec3::new(at.x - start.x, 0.0, at.z - start.z).length();
    (
        (top + half.y - at.y) / (2.0 * half.y),
        sideways / (2.0 * half.x),
    )
}

/// A thin box rests on its broad face at most 5 % of its thickness deep, from 1 mm plates 1 cm
/// to 1 m wide. A face's points are springs over their own effective masses, which the
/// levers of a broad face's corners shrink (a plate's corner carries a seventh of its mass, a
/// cube's a quarter), and capped at the step's stiffness a 1 mm plate 1 cm wide or wider sank
/// 5.4 % of its thickness at balanced (a 1 mm cube 3.1 %); the face may now be stiffer than
/// its points' cap by the root of their ratio (`MAX_LEVER_STIFFENING`).
#[test]
fn thin_plates_and_rods_rest_a_few_percent_of_their_thickness_deep() {
    let t = 0.0005f32; // half the thickness: 1 mm
    for preset in [PhysicsPreset::Balanced, PhysicsPreset::Precise] {
        for on_box in [false, true] {
            for (what, half) in [
                ("plate 1 cm", Vec3::new(0.005, t, 0.005)),
                ("plate 10 cm", Vec3::new(0.05, t, 0.05)),
                ("plate 1 m", Vec3::new(0.5, t, 0.5)),
                ("rod 10 cm", Vec3::new(0.05, t, t)),
                ("plank 2 mm x 30 cm", Vec3::new(0.15, 2.0 * t, 0.03)),
            ] {
                let (pen, sideways) = thin_box_on(preset, half, on_box);
                let on = if on_box { "a box" } else { "the ground" };
                println!(
                    "{preset} {what} on {on}: penetration {pen:.4} of its thickness \
                     (expected ≤ 0.05), moved {sideways:.2e} of its width"
                );
                assert!(
                    (0.0..=0.05).contains(&pen),
                    "{preset}: a {what} on {on} rests {pen} of its thickness deep, \
                     expected 0 … 5 %"
                );
                assert!(
                    sideways < 0.01,
                    "{preset}: a {what} on {on} moved {sideways} of its width sideways in 10 s"
                );
            }
        }
    }
}

/// Radius of the small ball on a box, m.
const SMALL_BALL: f32 = 0.0005;

/// A 1 mm ball on a box on the ground, run 3 s at `preset`: the reports of the ball's
/// contact, the box's mass over the ball's, and the ball's depth at the end, m.
fn small_ball_on_a_box(preset: PhysicsPreset) -> (Vec<OverloadedContact>, f32, f32) {
    let r = SMALL_BALL;
    let s = settings(preset);
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
    println!("{preset:?}: reports {reports:?}; measured depth {measured} m");
    let mine = reports
        .into_iter()
        .filter(|o| [o.body_a, o.body_b] == [bx, ball] || [o.body_a, o.body_b] == [ball, bx])
        .collect();
    let mass_ratio = w.body(bx).unwrap().mass() / w.body(ball).unwrap().mass();
    (mine, mass_ratio, measured)
}

#[test]
fn a_contact_the_step_cannot_hold_is_reported_once_with_the_preset_that_would() {
    // A 1 mm ball on a box at `fast`: the stiffest contact a 30 Hz step allows deflects it
    // about g / ω², several times its 2 % budget.
    let (mine, m, measured) = small_ball_on_a_box(PhysicsPreset::Fast);
    assert_eq!(
        mine.len(),
        1,
        "expected the ball's contact reported once: {mine:?}"
    );
    let o = mine[0];
    assert!(
        (o.expected_depth - measured).abs() < 0.3 * measured,
        "reported depth {} m, measured {measured} m (expected within 30 %)",
        o.expected_depth
    );
    assert!((o.allowed_depth - 0.02 * 2.0 * SMALL_BALL).abs() < 1e-9);
    assert!(o.load_ratio >= 1.0, "load ratio {}", o.load_ratio);
    assert!(o.mass_ratio.is_some_and(|x| (x - m).abs() < 1e-3 * m));
    // The preset named holds it: there the contact is not reported, and it settles within
    // the depth that names a contact (twice the budget).
    let holding = o.holding_preset.expect("some preset holds a 1 mm ball");
    assert_ne!(holding, PhysicsPreset::Fast);
    let (there, _, depth) = small_ball_on_a_box(holding);
    assert!(there.is_empty(), "reported at {holding:?}: {there:?}");
    assert!(
        depth <= 2.0 * o.allowed_depth,
        "{depth} m deep at {holding:?}, allowed {} m",
        o.allowed_depth
    );
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

/// A small body reaches the edge of what `f32` can place it to sooner: a 1 mm box resting on
/// a 1 km one, 1,000 m up, sank 7.3 % of itself at balanced (positions there are 61 µm apart,
/// 6 % of it) and nothing said so. Its range is where positions are spaced at most
/// `max_penetration_fraction` of it apart: 256 m for 1 mm at 2 %, 2,048 m for 1 cm.
#[test]
fn a_small_body_is_named_past_the_range_that_holds_its_size() {
    let s = PhysicsSettings {
        gravity: Vec3::ZERO,
        ..settings(PhysicsPreset::Balanced)
    };
    assert_eq!(s.precise_range_for(0.001), 256.0);
    assert_eq!(s.precise_range_for(0.01), 2_048.0);
    assert_eq!(s.precise_range_for(1.0), s.precise_range());
    assert_eq!(s.precise_range_for(f32::MAX), s.precise_range());
    let mut w = PhysicsWorld::new(s);
    let mut body = |y: f32, size: f32| {
        let b = w.insert_body(
            RigidBodyDesc::dynamic()
                .translation(Vec3::Y * y)
                .linvel(Vec3::X),
        );
        w.insert_collider(ColliderDesc::cuboid(0.5 * size, 0.5 * size, 0.5 * size), b);
        b
    };
    let tiny_near = body(100.0, 0.001);
    let tiny_far = body(1_000.0, 0.001);
    let small_far = body(1_000.0, 0.01);
    let large_far = body(1_000.0, 1.0);
    let first = w.step().far_bodies.clone();
    println!("far bodies: {first:?}");
    assert_eq!(first.len(), 1, "{first:?}");
    assert_eq!(first[0].body, tiny_far);
    assert_eq!(first[0].range, 256.0);
    assert!((first[0].size - 0.001).abs() < 1e-9);
    for b in [tiny_near, small_far, large_far] {
        assert!(first.iter().all(|f| f.body != b));
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

/// Sliding friction of the default material, and 30 % of what it holds under `mass`.
fn gentle_push(mass: f32) -> f32 {
    0.3 * onyx_physics::Material::default().dynamic_friction * mass * G
}

/// How far the light and the heavy box of `w` slide along x in 2 s, and the light box's
/// tilt (rad), with `force(w)` applied before each step.
fn slide(
    w: &mut PhysicsWorld,
    light: BodyHandle,
    heavy: BodyHandle,
    mut force: impl FnMut(&mut PhysicsWorld),
) -> (f32, f32, f32) {
    let x = |w: &PhysicsWorld, b| w.body(b).unwrap().translation().x;
    let (l0, h0) = (x(w, light), x(w, heavy));
    for _ in 0..(2.0 / w.settings().dt) as usize {
        force(w);
        w.step();
    }
    let tilt = w.body(light).unwrap().rotation().to_axis_angle().1;
    (x(w, light) - l0, x(w, heavy) - h0, tilt)
}

/// A heavy box on a light one (40 cm cubes, [`heavy_on_light_world`]) loaded sideways from
/// above: on an incline at half its friction angle (gravity tilted), and with the heavy box
/// pushed with 30 % of the force the pair's sliding friction holds. The light box carries
/// the load to the ground through friction at both faces; it must neither slide nor tip.
/// At fast, from 10:1 up the light box tipped over on its edge (the heavy one's off-centre
/// load rang on it for the one iteration a substep); `max_support_mass_ratio` 3 (was 10)
/// solved such a pair as 3:1, which held. Past the scaling onset the pair is now a heavy
/// body's column on the true masses (`heavy_on_light::SupportMass::Column`): damped for the
/// light box alone, its ground face let the 1000:1 pair on the incline rock past tipping at
/// balanced and throw the light box out; it is damped for the column it carries.
#[test]
fn a_heavy_box_on_a_light_one_holds_when_loaded_sideways_from_above() {
    for preset in PhysicsPreset::ALL {
        let (max_slide, max_tilt) = if preset == PhysicsPreset::Fast {
            (0.03, 0.1)
        } else {
            (0.005, 0.02)
        };
        for ratio in [1.0f32, 3.0, 10.0, 100.0, 1000.0] {
            for incline in [true, false] {
                let (mut w, light, heavy, _) = heavy_on_light_world(preset, ratio, 0.2, 0.2);
                let settle = (0.5 / w.settings().dt) as usize;
                run(&mut w, settle);
                let mass = w.body(light).unwrap().mass() + w.body(heavy).unwrap().mass();
                let (slid_light, slid_heavy, tilt) = if incline {
                    let slope = (0.5 * onyx_physics::Material::default().dynamic_friction).atan();
                    w.settings_mut().gravity = Vec3::new(G * slope.sin(), -G * slope.cos(), 0.0);
                    slide(&mut w, light, heavy, |_| {})
                } else {
                    slide(&mut w, light, heavy, |w| {
                        w.body_mut(heavy)
                            .unwrap()
                            .add_force(Vec3::X * gentle_push(mass));
                    })
                };
                let how = if incline { "on an incline" } else { "pushed" };
                assert!(
                    slid_light.abs() < max_slide && slid_heavy.abs() < max_slide,
                    "{preset}, {ratio}:1 {how}: slid {slid_light} m (light), {slid_heavy} m (heavy)"
                );
                assert!(
                    tilt < max_tilt,
                    "{preset}, {ratio}:1 {how}: the light box tilted {tilt} rad"
                );
            }
        }
    }
}

/// A heavy box resting off centre on a light one (40 cm cubes, its centre up to 10 cm aside
/// in x and half that in z, over the light box's face) for 6 s: at every preset the pair
/// stands, tilting less than 0.1 rad at fast and 0.03 rad at balanced and precise. Taken for
/// a heavy body's column stiffened for a tenth of the depth budget, the 1000:1 pair 10 cm
/// aside rocked at 4 Hz and tipped over at fast after two seconds
/// (`HEAVY_COLUMN_DEPTH_SHARE`), and with the soft columns' two passes a substep the pairs
/// 6–10 cm aside tipped within 6 s (`solve_stage`, `budget_column`; `examples/offset_heavy`
/// in the physics bench).
#[test]
fn a_heavy_box_off_centre_on_a_light_one_stands() {
    let mut failures = Vec::new();
    for preset in PhysicsPreset::ALL {
        let max_tilt = if preset == PhysicsPreset::Fast {
            0.1
        } else {
            0.03
        };
        for ratio in [3.0f32, 10.0, 30.0, 100.0, 1000.0] {
            for offset in [0.0f32, 0.03, 0.06, 0.1] {
                let (mut w, _, heavy, y0) = heavy_on_light_world(preset, ratio, 0.2, 0.2);
                if let Some(b) = w.body_mut(heavy) {
                    b.set_translation(Vec3::new(offset, y0, -0.5 * offset));
                }
                let mut tilt = 0.0f32;
                for _ in 0..(6.0 / w.settings().dt) as usize {
                    w.step();
                    let rotation = w.body(heavy).unwrap().rotation();
                    tilt = tilt.max(rotation.angle_between(onyx_physics::glam::Quat::IDENTITY));
                }
                // A NaN tilt fails too.
                if tilt.partial_cmp(&max_tilt) != Some(std::cmp::Ordering::Less) {
                    failures.push(format!(
                        "{preset}, {ratio}:1, {offset} m aside: tilted {tilt:.3} rad"
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// A light box (and a column of two) under a heavy one, the bottom box pushed sideways:
/// the ground's friction must hold the whole column's weight. Where the heavy-on-light
/// scaling (`support_mass_scale`) solves the light box as if it were
/// `max_support_mass_ratio` (3) times lighter than the heavy one, the normal rows under a
/// column of `n` light boxes carry only about `(n + ratio)·m·g` (past the scaling onset
/// these columns are now solved on the true masses, `SupportMass::Column`, where the column
/// of two slid 2.6 cm at fast, 1000:1, until the face under the light box the heavy one
/// rests on was taken into its column too). The push is 30 % of what the ground's sliding
/// friction holds under the column, but at most `0.6·(n + ratio)·m·g`, more than those
/// rows' own friction holds (`0.5·(n + ratio)·m·g`) and less than tips the light box (see
/// the ignored test below). Before the hidden load was given to the friction of the
/// supports (`HiddenLoads`) the single box slid 1.9–2.0 m in 2 s at fast and balanced
/// (3 cm at precise) at 100:1 and 1000:1; before it was passed down the column, the
/// column's bottom box slid 2 m at fast and 3–5 cm at balanced and precise.
#[test]
fn the_ground_under_a_light_box_holds_the_heavy_one_s_weight_in_friction() {
    for preset in PhysicsPreset::ALL {
        for ratio in [10.0f32, 100.0, 1000.0] {
            for column in [1usize, 2] {
                let (mut w, light, heavy, _) = heavy_on_light_world(preset, ratio, 0.2, 0.2);
                let bottom = if column == 2 {
                    push_under(&mut w, light, heavy)
                } else {
                    light
                };
                let cap = w.settings().max_support_mass_ratio;
                let settle = (0.5 / w.settings().dt) as usize;
                run(&mut w, settle);
                let m = w.body(light).unwrap().mass();
                let mass = column as f32 * m + w.body(heavy).unwrap().mass();
                let push = gentle_push(mass).min(0.6 * (column as f32 + cap) * m * G);
                let (slid, _, _) = slide(&mut w, bottom, heavy, move |w| {
                    w.body_mut(bottom).unwrap().add_force(Vec3::X * push);
                });
                assert!(
                    slid.abs() < 0.01,
                    "{preset}, {ratio}:1, a column of {column}: pushed with {push} N, the \
                     bottom box slid {slid} m in 2 s"
                );
            }
        }
    }
}

/// Puts a copy of `light` under it (and lifts it and `heavy` by its height), returning the
/// new bottom box.
fn push_under(w: &mut PhysicsWorld, light: BodyHandle, heavy: BodyHandle) -> BodyHandle {
    let half = 0.2;
    for b in [light, heavy] {
        let p = w.body(b).unwrap().translation();
        w.body_mut(b)
            .unwrap()
            .set_translation(p + Vec3::Y * 2.0 * half);
    }
    let bottom = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::Y * half));
    w.insert_collider(
        ColliderDesc::cuboid(half, half, half).density(1000.0),
        bottom,
    );
    bottom
}

/// The light box of [`heavy_on_light_world`] pushed with 30 % of the pair's sliding
/// friction: open (issue 15). Past `max_support_mass_ratio` the heavy box's moment on the
/// light one is scaled with its inverse mass, so the push's tilt is held by about
/// `(1 + 2·ratio)·m·g` of load: at 100:1 and 1000:1 the light box tips over and is squeezed
/// out (214 m and 1.6 km in 2 s). Run with `--ignored` to see it.
#[test]
#[ignore = "open: a light box under a heavy one tips under a sideways push past (1 + 2·ratio) times its weight"]
fn a_light_box_under_a_heavy_one_pushed_with_30_percent_of_the_pairs_friction_holds() {
    for preset in PhysicsPreset::ALL {
        for ratio in [10.0f32, 100.0, 1000.0] {
            let (mut w, light, heavy, _) = heavy_on_light_world(preset, ratio, 0.2, 0.2);
            let settle = (0.5 / w.settings().dt) as usize;
            run(&mut w, settle);
            let push = gentle_push(w.body(light).unwrap().mass() + w.body(heavy).unwrap().mass());
            let (slid, _, _) = slide(&mut w, light, heavy, move |w| {
                w.body_mut(light).unwrap().add_force(Vec3::X * push);
            });
            assert!(
                slid.abs() < 0.01,
                "{preset}, {ratio}:1: the light box slid {slid} m in 2 s"
            );
        }
    }
}
