//! Scene files written here (not the project's own), run by the real binary at each
//! `--physics` preset (`onyx run --headless --scene F --physics P --dump-state D`), and
//! checked against analytic answers: what a user who writes a scene and picks a preset gets.

use onyx_plugin_api::glam::Vec3;
use onyx_runtime::PhysicsPreset;
use onyx_tests::cli::{assert_exit, onyx, stderr};

/// A named body at the end of a run: name, position, linear velocity.
type Body = (String, Vec3, Vec3);

/// Runs `scene` (RON text) for `frames` fixed steps at `preset`; every named body at the
/// end, and what the host logged (warnings and up).
fn run(scene: &str, preset: PhysicsPreset, frames: u32) -> (Vec<Body>, String) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.ron");
    let dump = dir.path().join("state.json");
    std::fs::write(&path, scene).unwrap();
    let (preset, frames) = (preset.to_string(), frames.to_string());
    let (scene_arg, dump_arg) = (path.to_str().unwrap(), dump.to_str().unwrap());
    let out = onyx(&[
        "run",
        "--headless",
        "--physics",
        &preset,
        "--frames",
        &frames,
        "--scene",
        scene_arg,
        "--dump-state",
        dump_arg,
    ]);
    assert_exit(&out, 0);
    let state: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&dump).unwrap()).unwrap();
    let vec = |v: &serde_json::Value| {
        Vec3::from_slice(&serde_json::from_value::<Vec<f32>>(v.clone()).unwrap())
    };
    let bodies = state["entities"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["name"].is_string() && e["components"]["RigidBody"].is_object())
        .map(|e| {
            let c = &e["components"];
            (
                e["name"].as_str().unwrap().to_owned(),
                vec(&c["Transform"]["translation"]),
                vec(&c["RigidBody"]["linear_velocity"]),
            )
        })
        .collect();
    (bodies, stderr(&out))
}

fn body<'a>(bodies: &'a [Body], name: &str) -> &'a Body {
    bodies
        .iter()
        .find(|b| b.0 == name)
        .unwrap_or_else(|| panic!("no body {name} in the dump"))
}

/// An elastic ball on moon gravity with the restitution threshold at 0, both set by the
/// scene: at every preset the scene's gravity and threshold stay (a preset sets only the
/// step rate and substeps), and the ball keeps its drop energy bounce after bounce.
#[test]
fn an_elastic_ball_on_the_moon_keeps_its_energy_at_every_preset() {
    let g = 1.62f32;
    let (radius, drop) = (0.25f32, 2.0f32);
    let scene = format!(
        r#"(
    version: 3,
    physics: Some((preset: Balanced, gravity: Some((0.0, -{g}, 0.0)), restitution_threshold: Some(0.0))),
    entities: [
        (name: Some("ground"), transform: Some(()), collider: Some((shape: Plane, restitution: 1.0, friction: 0.0))),
        (
            name: Some("ball"),
            transform: Some((translation: (0.0, {y}, 0.0))),
            rigid_body: Some((kind: Dynamic, can_sleep: false)),
            collider: Some((shape: Sphere(radius: {radius}), restitution: 1.0, friction: 0.0)),
        ),
    ],
)"#,
        y = drop + radius,
    );
    // A bounce from 2 m on the moon takes 2·√(2h/g) = 3.1 s: 40 s is 12 bounces.
    let seconds = 40.0;
    for preset in PhysicsPreset::ALL {
        let (hz, substeps) = (preset.step_hz(), preset.substeps() as f32);
        let (bodies, _) = run(&scene, preset, (seconds * hz) as u32);
        let (_, p, v) = body(&bodies, "ball");
        // The stored velocity leads the instantaneous one by half a substep of gravity
        // (semi-implicit Euler); the energy is that of the instantaneous one.
        let v_now = v.y - 0.5 * g / (hz * substeps);
        let height = (p.y - radius).max(0.0) + 0.5 * (v_now * v_now + v.x * v.x + v.z * v.z) / g;
        assert!(
            ((height - drop) / drop).abs() < 0.01,
            "{preset}: the ball's energy is that of a {height} m drop after {seconds} s \
             (dropped from {drop} m; a 9.81 m/s² preset gravity would read far off)"
        );
    }
}

/// A 1000 kg box resting on a 1 kg box of the same size on the ground, written by a user,
/// for boxes from 1 cm to 10 m, with friction and without: at balanced the heavy box sinks
/// less than 2 cm into the light one and at precise less than 1 cm (the issue's bounds),
/// and at both less than 5 % of the box (the penetration bound). Where fast does not hold
/// it within 5 % (small boxes: 30 Hz × 2 is too coarse for them), the host says so, with
/// the mass ratio and the preset that would. (The 10 m boxes with friction sank 2.4 cm at
/// balanced before a heavy body's column was held to `HEAVY_COLUMN_RESTING_DEPTHS`.)
#[test]
fn a_thousand_to_one_box_on_a_box_holds_or_is_reported_at_every_preset() {
    for (half, friction) in [0.005f32, 0.02, 0.25, 5.0]
        .into_iter()
        .flat_map(|h| [(h, 0.5f32), (h, 0.0)])
    {
        let scene = format!(
            r#"(
    version: 3,
    entities: [
        (name: Some("ground"), transform: Some(()), collider: Some((shape: Plane, friction: {friction}))),
        (
            name: Some("light"),
            transform: Some((translation: (0.0, {half}, 0.0))),
            rigid_body: Some((kind: Dynamic, mass: 1.0)),
            collider: Some((shape: Box(half_extents: ({half}, {half}, {half})), friction: {friction})),
        ),
        (
            name: Some("heavy"),
            transform: Some((translation: (0.0, {top}, 0.0))),
            rigid_body: Some((kind: Dynamic, mass: 1000.0)),
            collider: Some((shape: Box(half_extents: ({half}, {half}, {half})), friction: {friction})),
        ),
    ],
)"#,
            top = 3.0 * half,
        );
        let size = 2.0 * half;
        for (preset, bound) in [
            (PhysicsPreset::Fast, f32::INFINITY),
            (PhysicsPreset::Balanced, 0.02),
            (PhysicsPreset::Precise, 0.01),
        ] {
            // 480 steps: 16 s at fast, 4 s at precise.
            let (bodies, log) = run(&scene, preset, 480);
            let (_, light, _) = body(&bodies, "light");
            let (_, heavy, v) = body(&bodies, "heavy");
            let sink = light.y + size - heavy.y;
            let held = sink < bound.min(0.05 * size) && v.length() < 0.05 * size.max(1.0);
            let reported = log.contains("mass ratio 1000:1") && log.contains("holds it");
            assert!(
                held || (preset == PhysicsPreset::Fast && reported),
                "{preset}, {size} m boxes, friction {friction}: the heavy box is {sink} m into \
                 the light one \
                 (bound {bound} m and 5 % of {size} m), moving at {v}; the host logged:\n{log}"
            );
        }
    }
}

/// 50 elastic balls of radii 10–20 cm, a third of them with CCD, thrown at up to 3 m/s inside
/// a closed box of six static walls, every surface e = 1 without friction and the
/// restitution threshold at 0, all written by a user as a scene file: after 10,000 steps at
/// every preset the crowd has the energy it started with, within 2 % (the issue's bound for
/// such a crowd is 5 %; within 7e-5 at every preset when written, with the integrator's
/// phase; the plain energy swings by 0.2–0.4 % at fast without it).
#[test]
fn an_elastic_crowd_in_a_closed_box_keeps_its_energy_at_every_preset() {
    let (g, half, wall) = (9.81f32, 2.0f32, 0.25f32);
    let mut entities = Vec::new();
    for axis in 0..3 {
        for side in [-1.0f32, 1.0] {
            let mut he = [half + 2.0 * wall; 3];
            he[axis] = wall;
            let mut c = [0.0f32; 3];
            c[axis] = side * (half + wall);
            entities.push(format!(
                "(transform: Some((translation: ({:?}, {:?}, {:?}))), collider: Some((shape: \
                 Box(half_extents: ({:?}, {:?}, {:?})), restitution: 1.0, friction: 0.0)))",
                c[0], c[1], c[2], he[0], he[1], he[2]
            ));
        }
    }
    // A start of the crowd that the engine was not tuned on.
    let mut rng = fastrand::Rng::with_seed(0x5EED);
    let mut uniform = |lo: f32, hi: f32| lo + (hi - lo) * rng.f32();
    // Name, radius, start position and velocity.
    let mut balls = Vec::new();
    for i in 0..50 {
        let (gx, gy, gz) = ((i % 5) as f32, ((i / 5) % 2) as f32, (i / 10) as f32);
        let r = uniform(0.1, 0.2);
        let p = Vec3::new(
            -1.6 + 0.8 * gx + uniform(-0.15, 0.15),
            -1.0 + 1.2 * gy + uniform(-0.15, 0.15),
            -1.6 + 0.8 * gz + uniform(-0.15, 0.15),
        );
        let v = Vec3::new(uniform(-3.0, 3.0), uniform(-3.0, 3.0), uniform(-3.0, 3.0));
        entities.push(format!(
            "(name: Some(\"ball {i}\"), transform: Some((translation: ({:?}, {:?}, {:?}))), \
             rigid_body: Some((kind: Dynamic, can_sleep: false, ccd: {}, linear_velocity: \
             ({:?}, {:?}, {:?}))), collider: Some((shape: Sphere(radius: {r:?}), restitution: \
             1.0, friction: 0.0)))",
            p.x,
            p.y,
            p.z,
            i % 3 == 0,
            v.x,
            v.y,
            v.z
        ));
        balls.push((format!("ball {i}"), r, p, v));
    }
    let scene = format!(
        "(version: 3, physics: Some((preset: Balanced, restitution_threshold: Some(0.0))), \
         entities: [{}])",
        entities.join(",\n")
    );
    // Kinetic and potential energy (from the floor) of balls of equal density, in units of
    // the density: the mass is ∝ r³. `lead` is how far the stored velocity leads the
    // instantaneous one in y (half a substep of gravity, semi-implicit Euler).
    let energy = |state: &[(f32, Vec3, Vec3)], lead: f32| -> f32 {
        state
            .iter()
            .map(|&(r, p, v)| {
                let v = Vec3::new(v.x, v.y - lead, v.z);
                r * r * r * (0.5 * v.length_squared() + g * (p.y + half))
            })
            .sum()
    };
    let start: Vec<_> = balls.iter().map(|(_, r, p, v)| (*r, *p, *v)).collect();
    for preset in PhysicsPreset::ALL {
        let h = 1.0 / (preset.step_hz() * preset.substeps() as f32);
        let (bodies, _) = run(&scene, preset, 10_000);
        let end: Vec<_> = balls
            .iter()
            .map(|(name, r, _, _)| {
                let (_, p, v) = body(&bodies, name);
                (*r, *p, *v)
            })
            .collect();
        let inside = end
            .iter()
            .all(|(r, p, _)| p.abs().max_element() < half - r + 0.01);
        let change = energy(&end, 0.5 * g * h) / energy(&start, 0.5 * g * h) - 1.0;
        println!("{preset}: the crowd's energy changed by {change:+.2e} of its start");
        assert!(
            inside && change.abs() < 0.02,
            "{preset}: after 10,000 steps the elastic crowd's energy changed by {change} of \
             its start (bound 2 %), every ball inside the box: {inside}"
        );
    }
}
