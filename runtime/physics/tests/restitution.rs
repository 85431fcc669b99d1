//! Restitution: rebound heights `e²·h`, elastic bounces that keep their energy, the threshold.
//!
//! `e = 1` used not to be elastic: each bounce lost about `g·dt` of speed (the restitution
//! used the velocity at step start, before the fall inside the impact step), so a ball
//! dropped from 2 m stopped bouncing within 24 s; impacts slower than a fixed 1 m/s were
//! fully inelastic.
mod common;
use common::*;
use onyx_physics::glam::{Quat, Vec3};
use onyx_physics::{
    BodyHandle, ColliderDesc, PhysicsPreset, PhysicsSettings, PhysicsWorld, RigidBodyDesc,
};

fn settings(preset: PhysicsPreset, threshold: f32) -> PhysicsSettings {
    PhysicsSettings {
        restitution_threshold: threshold,
        sleep_enabled: false,
        ..preset.settings()
    }
}

/// A ball of radius `r` with its bottom `h` above a ground half space, both with
/// restitution `e`, no friction.
fn drop_ball(s: PhysicsSettings, e: f32, h: f32, r: f32) -> (PhysicsWorld, BodyHandle) {
    let mut w = PhysicsWorld::new(s);
    let g = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(
        ColliderDesc::half_space(Vec3::Y)
            .restitution(e)
            .friction(0.0),
        g,
    );
    let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, h + r, 0.0)));
    w.insert_collider(ColliderDesc::sphere(r).restitution(e).friction(0.0), b);
    (w, b)
}

/// Apex heights (bottom above the ground) of the first `n` rebounds.
fn rebound_apexes(w: &mut PhysicsWorld, b: BodyHandle, r: f32, n: usize) -> Vec<f32> {
    let mut apexes = Vec::new();
    let mut prev_vy = 0.0f32;
    let mut apex = f32::MIN;
    let mut rising = false;
    let max_steps = (n as f32 * 3.0 / w.settings().dt) as usize;
    for _ in 0..max_steps {
        w.step();
        let body = w.body(b).expect("ball exists");
        let (vy, y) = (body.linvel().y, body.translation().y - r);
        if prev_vy <= 0.0 && vy > 0.0 {
            rising = true;
            apex = y;
        }
        if rising {
            apex = apex.max(y);
            if vy <= 0.0 {
                apexes.push(apex);
                rising = false;
                if apexes.len() == n {
                    break;
                }
            }
        }
        prev_vy = vy;
    }
    apexes
}

#[test]
fn elastic_ball_rebounds_to_its_drop_height_after_100_bounces() {
    let h = 2.0;
    for preset in PhysicsPreset::ALL {
        let (mut w, b) = drop_ball(settings(preset, 0.0), 1.0, h, 0.1);
        let apexes = rebound_apexes(&mut w, b, 0.1, 100);
        let last = apexes.last().copied().unwrap_or(0.0);
        let lowest = apexes.iter().copied().fold(f32::MAX, f32::min);
        println!(
            "{preset}: {} rebounds, 100th apex {last:.4} m, lowest {lowest:.4} m, expected {h} m",
            apexes.len()
        );
        assert_eq!(apexes.len(), 100, "{preset}: the ball stopped bouncing");
        // The target is 1 % at balanced; fast and precise are held to the same.
        assert!(
            (last - h).abs() < 0.01 * h,
            "{preset}: 100th rebound apex {last} m, expected {h} m ± 1 %"
        );
    }
}

#[test]
fn rebound_height_ratio_is_e_squared_at_every_preset() {
    let h = 2.0;
    for preset in PhysicsPreset::ALL {
        for e in [0.3f32, 0.5, 0.7, 0.9] {
            let (mut w, b) = drop_ball(settings(preset, 0.0), e, h, 0.25);
            let apex = rebound_apexes(&mut w, b, 0.25, 1)[0];
            let (measured, expected) = (apex / h, e * e);
            println!("{preset} e = {e}: h1/h0 measured {measured:.4}, expected {expected:.4}");
            assert!(
                (measured - expected).abs() < 0.01,
                "{preset}, e = {e}: rebound ratio {measured}, expected e² = {expected} ± 0.01"
            );
        }
    }
}

/// Two equal balls, no gravity, meeting head-on at `speed` each; returns their velocities
/// along x after the impact.
fn head_on(speed: f32, threshold: f32, e: f32) -> (f32, f32) {
    let s = PhysicsSettings {
        gravity: Vec3::ZERO,
        ..settings(PhysicsPreset::Balanced, threshold)
    };
    let mut w = PhysicsWorld::new(s);
    let mut ball = |x: f32, v: f32| {
        let b = w.insert_body(
            RigidBodyDesc::dynamic()
                .translation(Vec3::X * x)
                .linvel(Vec3::X * v),
        );
        w.insert_collider(ColliderDesc::sphere(0.1).restitution(e).friction(0.0), b);
        b
    };
    let (a, b) = (ball(-0.5, speed), ball(0.5, -speed));
    let steps = (2.0 / speed / s.dt) as usize;
    run(&mut w, steps);
    (w.body(a).unwrap().linvel().x, w.body(b).unwrap().linvel().x)
}

#[test]
fn elastic_balls_meeting_slowly_swap_velocities() {
    // Equal masses, e = 1: momentum and energy conservation give an exchange of velocities.
    for speed in [0.05f32, 0.5, 5.0] {
        let (va, vb) = head_on(speed, 0.0, 1.0);
        println!("meeting at ±{speed} m/s: after {va:.4}, {vb:.4}, expected ∓{speed}");
        assert!(
            (va + speed).abs() < 0.01 * speed && (vb - speed).abs() < 0.01 * speed,
            "meeting at ±{speed} m/s with e = 1: velocities after {va}, {vb}, expected \
             {}, {speed} ± 1 %",
            -speed
        );
    }
}

#[test]
fn impacts_slower_than_the_threshold_do_not_bounce() {
    let threshold = PhysicsSettings::default().restitution_threshold;
    // Closing at twice the speed each: relative approach speed 2·v.
    let (va, vb) = head_on(0.2 * threshold, threshold, 1.0);
    println!(
        "closing at {} m/s, threshold {threshold}: after {va}, {vb}",
        0.4 * threshold
    );
    assert!(
        va.abs() < 1e-3 && vb.abs() < 1e-3,
        "impact below the threshold bounced: {va}, {vb}, expected 0, 0"
    );
    let (va, vb) = head_on(threshold, threshold, 1.0);
    println!(
        "closing at {} m/s, threshold {threshold}: after {va}, {vb}",
        2.0 * threshold
    );
    assert!(
        va < 0.0 && vb > 0.0,
        "impact above the threshold did not bounce: {va}, {vb}"
    );
}

/// 50 elastic balls in a closed elastic box at every preset, without gravity and under it
/// from four starts. Before the restitution passes drove every loaded point (see
/// `onyx_physics::solver::restitution`), balanced lost 24 % under gravity and fast 20 %
/// without it; before each elastic impact's energy was projected back onto its start (see
/// `onyx_physics::solver::elastic_energy`), fast lost 2.5–8.7 % under gravity over seven
/// starts (now at most 0.6 %).
#[test]
fn elastic_spheres_in_a_closed_box_keep_their_energy() {
    for preset in PhysicsPreset::ALL {
        let starts = std::iter::once((0.0, 15)).chain((1..=4).map(|seed| (G, seed)));
        for (gravity, seed) in starts {
            let worst = elastic_box_from(preset, gravity, seed, Crowd::Equal);
            assert!(
                worst < 0.05,
                "{preset}, g = {gravity}, start {seed}: energy of 50 elastic balls changed by up \
                 to {worst} of the start, expected < 5 %"
            );
        }
    }
}

/// 50 elastic balls of radii 8–20 cm and densities 200–3,200 kg/m³ (masses up to ~250:1)
/// in the closed box under gravity, CCD on (a light ball caught between a heavy one and a
/// wall leaves at up to 40 m/s, as it should), at every preset. Over six starts they stay
/// within 1.4 %, 0.14 % and 0.09 % at fast, balanced and precise; before each elastic
/// impact's energy was projected back onto its start they gained up to 4,000×, 149 % and
/// 1.1 %, and before a body stopped by CCD kept the energy it has where it stops (see
/// `pipeline/writeback_stage.rs`) 5–6 %, 1.3 % and 0.2 %.
#[test]
fn elastic_spheres_of_mixed_sizes_and_masses_keep_their_energy() {
    for preset in PhysicsPreset::ALL {
        let worst = elastic_box_from(preset, G, 1, Crowd::Mixed);
        assert!(
            worst < 0.05,
            "{preset}: energy of 50 mixed elastic balls changed by up to {worst} of the start, \
             expected < 5 %"
        );
    }
}

/// A frictionless e = 1 box (60 × 40 × 20 cm) dropped from 2.5 m on an e = 1 floor, flat and
/// tilted three ways, bouncing and tumbling for 20 s: its energy (with the rotation's) stays
/// within 5 % at balanced and precise (2.8 % and 0.5 % at worst) and 15 % at fast (11.7 %: a
/// tumbling box at 30 Hz spins 30–40 rad/s, a radian a step). Before each elastic impact's energy was projected back onto its
/// start it gained up to 2.1× at fast, 1.7× at balanced and precise.
#[test]
fn an_elastic_box_tumbling_on_the_floor_keeps_its_energy() {
    let tilts = [
        Quat::IDENTITY,
        Quat::from_rotation_x(0.3),
        Quat::from_scaled_axis(Vec3::new(0.4, 0.2, 0.7)),
        Quat::from_scaled_axis(Vec3::new(1.1, -0.5, 0.3)),
    ];
    for preset in PhysicsPreset::ALL {
        let bound = if preset == PhysicsPreset::Fast {
            0.15
        } else {
            0.05
        };
        for (k, tilt) in tilts.into_iter().enumerate() {
            let s = settings(preset, 0.0);
            let h = s.dt / s.substeps as f32;
            let mut w = PhysicsWorld::new(s);
            let floor = w.insert_body(RigidBodyDesc::fixed());
            w.insert_collider(
                ColliderDesc::half_space(Vec3::Y)
                    .restitution(1.0)
                    .friction(0.0),
                floor,
            );
            let b = w.insert_body(
                RigidBodyDesc::dynamic()
                    .translation(Vec3::Y * 2.5)
                    .rotation(tilt),
            );
            w.insert_collider(
                ColliderDesc::cuboid(0.3, 0.2, 0.1)
                    .restitution(1.0)
                    .friction(0.0),
                b,
            );
            // The integrator's energy (semi-implicit Euler's phase included, see
            // `onyx_physics::solver::elastic_energy::shadow_energy`).
            let energy = |w: &PhysicsWorld| {
                let x = w.body(b).unwrap();
                let (m, v, spin) = (x.mass(), x.linvel(), x.angvel());
                0.5 * m * v.length_squared()
                    + 0.5 * spin.dot(x.world_inertia() * spin)
                    + m * G * x.translation().y
                    - 0.5 * m * G * h * v.y
            };
            let e0 = energy(&w);
            let mut worst = 0.0f32;
            for _ in 0..(20.0 / s.dt) as usize {
                w.step();
                worst = worst.max((energy(&w) / e0 - 1.0).abs());
            }
            println!("{preset}, tilt {k}: energy off by up to {worst:.4} of the start");
            assert!(
                worst < bound,
                "{preset}, tilt {k}: an elastic box's energy changed by up to {worst} of the \
                 start, expected < {bound}"
            );
        }
    }
}

/// A column of `n` elastic balls of radius `r` on an elastic floor, the lowest resting on
/// it, the others above with 50 cm gaps, no friction.
fn column(s: PhysicsSettings, n: usize, r: f32) -> (PhysicsWorld, Vec<BodyHandle>) {
    let mut w = PhysicsWorld::new(s);
    let floor = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(
        ColliderDesc::half_space(Vec3::Y)
            .restitution(1.0)
            .friction(0.0),
        floor,
    );
    let balls = (0..n)
        .map(|i| {
            let y = r + i as f32 * (2.0 * r + 0.5);
            let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::Y * y));
            w.insert_collider(ColliderDesc::sphere(r).restitution(1.0).friction(0.0), b);
            b
        })
        .collect();
    (w, balls)
}

/// A ball dropped onto an equal one lying on the floor: in the simultaneous solution the
/// floor holds the lower ball, and the upper one leaves at its impact speed, back to its
/// drop height. The lower ball took half the impact and the upper one rose to a quarter of
/// its drop at fast before every loaded point was driven; closing the last gap under `g`
/// (the lower ball does not fall) was missing 18 % of the drop at fast.
#[test]
fn a_ball_landing_on_a_resting_ball_rebounds_to_its_drop_height() {
    let r = 0.15;
    for preset in PhysicsPreset::ALL {
        let (mut w, balls) = column(settings(preset, 0.0), 2, r);
        let drop = w.body(balls[1]).unwrap().translation().y;
        let (mut apex, mut fell, mut lower_highest) = (f32::MIN, false, f32::MIN);
        for _ in 0..(2.0 / w.settings().dt) as usize {
            w.step();
            let upper = w.body(balls[1]).unwrap();
            let lower = w.body(balls[0]).unwrap();
            lower_highest = lower_highest.max(lower.translation().y);
            if upper.linvel().y > 0.0 {
                fell = true;
            }
            if fell {
                apex = apex.max(upper.translation().y);
                if upper.linvel().y < 0.0 {
                    break;
                }
            }
        }
        let rise = (apex - 3.0 * r) / (drop - 3.0 * r);
        println!(
            "{preset}: rebound to {rise:.4} of the drop, lower ball up to {:.2} mm",
            (lower_highest - r) * 1e3
        );
        assert!(
            (rise - 1.0).abs() < 0.02,
            "{preset}: the upper ball rose to {rise} of its drop, expected 1 ± 2 %"
        );
    }
}

/// The column of [`column`], 2–4 balls, over 20 s: colliding in one step with a ball that has
/// just left the floor, a ball must not be thrown up as if that ball had hit the floor
/// again (a column of two gained 45 % at fast and precise), nor lose what the lowest ball
/// takes from the impacts (a column of two kept 36 % at fast and 37 % at balanced before the
/// restitution passes drove every loaded point, and 78–89 % before the rebound left from
/// where the held lower ball started the step). Before each elastic impact's energy was
/// projected back onto its start (`onyx_physics::solver::elastic_energy`), columns of three
/// and four kept 81–100 % (the soft contacts' spring lifts the lowest ball a millimetre or
/// two within an impact step, and an impact on a hopping ball lost or gained the potential
/// energy the upper one spent closing the gap) and one of two reached 1.048 at precise; all
/// nine now stay within 0.969–1.029.
#[test]
fn a_column_of_elastic_balls_keeps_most_of_its_energy_and_gains_none() {
    for preset in PhysicsPreset::ALL {
        for n in 2..=4 {
            let s = settings(preset, 0.0);
            let r = 0.15;
            let (mut w, balls) = column(s, n, r);
            let e0 = energy(&w, &balls, G, r);
            let (mut most, mut least) = (0.0f32, f32::MAX);
            for _ in 0..(20.0 / s.dt) as usize {
                w.step();
                let e = energy(&w, &balls, G, r) / e0;
                (most, least) = (most.max(e), least.min(e));
            }
            println!("{preset}, {n} balls: energy between {least:.3} and {most:.3} of the start");
            assert!(
                most < 1.05 && least > 0.95,
                "{preset}: a column of {n} elastic balls ranged over {least}–{most} of its \
                 energy, expected 0.95–1.05"
            );
        }
    }
}

/// Eight bouncy boxes resting in a stack stand as still as inelastic ones at balanced and
/// precise: restitution holds only points an impact reaches. Holding every loaded point of
/// a bouncy manifold, the e = 0.5 stack swayed 18 cm at balanced (1.4 cm with e = 0). At
/// fast, bouncy stacks of 8 and 10 boxes topple (as an e = 1 stack of 4 or more did before;
/// see the report).
#[test]
fn a_resting_stack_of_bouncy_boxes_stands() {
    for preset in [PhysicsPreset::Balanced, PhysicsPreset::Precise] {
        for e in [0.5f32, 1.0] {
            let s = settings(preset, 0.1);
            let mut w = PhysicsWorld::new(s);
            let ground = w.insert_body(RigidBodyDesc::fixed());
            w.insert_collider(ColliderDesc::half_space(Vec3::Y).restitution(e), ground);
            let boxes: Vec<_> = (0..8)
                .map(|i| {
                    let p = Vec3::Y * (0.5 + i as f32);
                    let b = w.insert_body(RigidBodyDesc::dynamic().translation(p));
                    w.insert_collider(ColliderDesc::cuboid(0.5, 0.5, 0.5).restitution(e), b);
                    (b, p)
                })
                .collect();
            let mut worst = 0.0f32;
            for _ in 0..(10.0 / s.dt) as usize {
                w.step();
                for &(b, p) in &boxes {
                    worst = worst.max((w.body(b).unwrap().translation() - p).length());
                }
            }
            println!(
                "{preset}, e = {e}: the stack moved at most {:.1} mm",
                worst * 1e3
            );
            assert!(
                worst < 0.03,
                "{preset}, e = {e}: a box of the stack moved {worst} m, expected < 3 cm"
            );
        }
    }
}

/// Which balls [`elastic_box_from`] fills its box with.
#[derive(Clone, Copy, PartialEq)]
enum Crowd {
    /// Radius 15 cm, density 1,000 kg/m³.
    Equal,
    /// Radii 8–20 cm, densities 200–3,200 kg/m³, CCD on.
    Mixed,
}

/// 50 balls, e = 1, no friction, in a closed box of static walls with e = 1, 10,000 steps,
/// the balls' start drawn from `seed`; returns the largest relative change of the total
/// energy (kinetic + potential).
fn elastic_box_from(preset: PhysicsPreset, gravity: f32, seed: u64, crowd: Crowd) -> f32 {
    let s = PhysicsSettings {
        gravity: Vec3::Y * -gravity,
        ..settings(preset, 0.0)
    };
    let mut w = PhysicsWorld::new(s);
    let half = 2.0;
    let wall = 0.5;
    let walls = w.insert_body(RigidBodyDesc::fixed());
    for axis in 0..3 {
        for side in [-1.0f32, 1.0] {
            let mut he = Vec3::splat(half + wall);
            he[axis] = wall;
            let mut c = Vec3::ZERO;
            c[axis] = side * (half + wall);
            w.insert_collider(
                ColliderDesc::cuboid(he.x, he.y, he.z)
                    .translation(c)
                    .restitution(1.0)
                    .friction(0.0),
                walls,
            );
        }
    }
    let mut rng = Rng(seed);
    let mut balls = Vec::new();
    for i in 0..50 {
        let cell = Vec3::new((i % 5) as f32, ((i / 5) % 5) as f32, (i / 25) as f32);
        let p = (cell - Vec3::new(2.0, 2.0, 0.5)) * 0.7 + rng.vec3(-0.05, 0.05);
        let v = rng.vec3(-3.0, 3.0);
        let (r, density) = match crowd {
            Crowd::Equal => (0.15, 1000.0),
            Crowd::Mixed => {
                let k = rng.vec3(0.0, 1.0);
                (0.08 + 0.12 * k.x, 200.0 + 3000.0 * k.y)
            }
        };
        let b = w.insert_body(
            RigidBodyDesc::dynamic()
                .translation(p)
                .linvel(v)
                .ccd_enabled(crowd == Crowd::Mixed),
        );
        w.insert_collider(
            ColliderDesc::sphere(r)
                .density(density)
                .restitution(1.0)
                .friction(0.0),
            b,
        );
        balls.push((b, r));
    }
    // Potential energy measured from each ball resting on the floor, so the figure is not
    // dominated by it.
    let e_of = |w: &PhysicsWorld| -> f32 {
        balls
            .iter()
            .map(|&(b, r)| energy(w, &[b], gravity, -half + r))
            .sum()
    };
    let e0 = e_of(&w);
    let mut worst = 0.0f32;
    for i in 0..10_000 {
        w.step();
        if i % 100 == 99 {
            worst = worst.max((e_of(&w) / e0 - 1.0).abs());
        }
    }
    let e1 = e_of(&w);
    println!(
        "{preset}, g = {gravity}, start {seed}: energy after 10,000 steps {:.4} of the start, \
         worst {worst:.4} (expected 1, ± 5 %)",
        e1 / e0
    );
    worst
}

/// Kinetic plus potential energy of `balls` under `gravity` (m/s², pulling along −y), the
/// potential measured from height `floor`, J.
fn energy(w: &PhysicsWorld, balls: &[BodyHandle], gravity: f32, floor: f32) -> f32 {
    balls
        .iter()
        .map(|&b| {
            let body = w.body(b).unwrap();
            let m = body.mass();
            0.5 * m * body.linvel().length_squared() + m * gravity * (body.translation().y - floor)
        })
        .sum()
}
