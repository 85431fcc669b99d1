//! Physics in the host: bodies from components and scene files, stepped in the fixed step,
//! checked against what physics says.

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::{
    Collider, Ctx, Entity, Event, Flow, LockedAxes, Name, PhysicsEvent, Plugin, RigidBody,
    Transform,
};
use onyx_runtime::HeadlessHost;
use std::sync::{Arc, Mutex};

const G: f32 = 9.81;

/// A dropped stack, run by the real binary: every box ends resting where physics says.
#[test]
fn a_dropped_stack_from_a_scene_file_comes_to_rest_box_on_box() {
    let dir = tempfile::tempdir().unwrap();
    let dump = dir.path().join("state.json");
    let scene = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/scenes/stack.ron");
    let out = std::process::Command::new(onyx_tests::onyx_binary())
        .args(["run", "--headless", "--frames", "480", "--scene"])
        .arg(&scene)
        .arg("--dump-state")
        .arg(&dump)
        .env("RUST_LOG", "warn")
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let state: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&dump).unwrap()).unwrap();
    for i in 0..5 {
        let entity = state["entities"]
            .as_array()
            .unwrap()
            .iter()
            .find(|e| e["name"] == format!("box {i}"))
            .unwrap();
        let c = &entity["components"];
        let p: Vec<f32> = serde_json::from_value(c["Transform"]["translation"].clone()).unwrap();
        let expected_y = 0.5 + i as f32;
        // Soft contacts sink a few millimetres per loaded contact: 1 cm per box is generous.
        let tolerance = 0.01 * (i + 1) as f32;
        assert!(
            (p[1] - expected_y).abs() < tolerance,
            "box {i} rests at y = {} (expected {expected_y} ± {tolerance})",
            p[1]
        );
        assert!(
            p[0].abs() < 0.01 && p[2].abs() < 0.01,
            "box {i} drifted sideways: {p:?}"
        );
        let v: Vec<f32> =
            serde_json::from_value(c["RigidBody"]["linear_velocity"].clone()).unwrap();
        assert!(
            Vec3::from_slice(&v).length() < 0.05,
            "box {i} still moves: {v:?}"
        );
        assert_eq!(
            c["RigidBody"]["grounded"], true,
            "box {i} rests on something"
        );
        assert!(c["Collider"]["shape"]["Box"].is_object(), "{c}");
    }
}

type Script = Box<dyn FnMut(&mut Ctx, u64) + Send>;

/// Runs a closure each frame with the frame number; records physics events.
struct Scripted {
    script: Script,
    frame: u64,
    events: Arc<Mutex<Vec<PhysicsEvent>>>,
}

impl Plugin for Scripted {
    fn on_event(&mut self, _: &mut Ctx, event: &Event) {
        if let Event::Physics(e) = event {
            self.events.lock().unwrap().push(*e);
        }
    }
    fn on_update(&mut self, ctx: &mut Ctx, _: f32) -> Flow {
        (self.script)(ctx, self.frame);
        self.frame += 1;
        Flow::Continue
    }
}

fn run(
    frames: u32,
    script: impl FnMut(&mut Ctx, u64) + Send + 'static,
) -> (HeadlessHost, Vec<PhysicsEvent>) {
    let events = Arc::new(Mutex::new(Vec::new()));
    let mut host = HeadlessHost::new();
    let plugin = Scripted {
        script: Box::new(script),
        frame: 0,
        events: events.clone(),
    };
    host.add_plugin("scripted", plugin).unwrap();
    host.step(frames);
    let events = events.lock().unwrap().clone();
    (host, events)
}

fn ground(ctx: &mut Ctx) -> Entity {
    ctx.spawn((Name::new("ground"), Transform::IDENTITY, Collider::plane()))
        .unwrap()
}

#[test]
fn a_body_falls_freely_at_g() {
    // 0.5 s of free fall from 100 m: y = 100 - g t² / 2 (semi-implicit Euler: within 1 %).
    let (host, _) = run(31, |ctx, frame| {
        if frame == 0 {
            let body = (
                Name::new("ball"),
                Transform::from_xyz(0.0, 100.0, 0.0),
                RigidBody::dynamic(),
                Collider::sphere(0.5),
            );
            ctx.spawn(body).unwrap();
        }
    });
    let (_, t) = host.find::<Transform>("ball").unwrap();
    let (_, rb) = host.find::<RigidBody>("ball").unwrap();
    let fallen = 100.0 - t.translation.y;
    let expected = 0.5 * G * 0.5 * 0.5;
    assert!(
        (fallen - expected).abs() < 0.02 * expected,
        "fell {fallen} m, expected {expected}"
    );
    assert!(
        (rb.linear_velocity.y + G * 0.5).abs() < 0.01 * G * 0.5,
        "v = {}",
        rb.linear_velocity.y
    );
}

#[test]
fn an_impulse_changes_velocity_by_j_over_m_and_set_velocity_sets_it() {
    let (host, _) = run(3, |ctx, frame| match frame {
        0 => {
            let body = RigidBody::dynamic().with_mass(2.0);
            let mut b = body;
            b.gravity_scale = 0.0;
            ctx.spawn((
                Name::new("puck"),
                Transform::IDENTITY,
                b,
                Collider::sphere(0.5),
            ))
            .unwrap();
            let other = RigidBody {
                gravity_scale: 0.0,
                ..RigidBody::dynamic()
            };
            ctx.spawn((
                Name::new("spun"),
                Transform::from_xyz(5.0, 0.0, 0.0),
                other,
                Collider::sphere(0.5),
            ))
            .unwrap();
        }
        1 => {
            let puck = ctx
                .entities()
                .to_vec()
                .into_iter()
                .find(|e| ctx.get::<Name>(*e).is_ok_and(|n| n.as_str() == "puck"))
                .unwrap();
            ctx.apply_impulse(puck, Vec3::new(4.0, 0.0, 0.0)).unwrap();
            let spun = ctx
                .entities()
                .to_vec()
                .into_iter()
                .find(|e| ctx.get::<Name>(*e).is_ok_and(|n| n.as_str() == "spun"))
                .unwrap();
            ctx.set_velocity(spun, Vec3::new(0.0, 0.0, 3.0), Vec3::new(0.0, 1.0, 0.0))
                .unwrap();
            let error = ctx
                .apply_force(puck, Vec3::new(f32::NAN, 0.0, 0.0))
                .unwrap_err();
            assert!(error.to_string().contains("NaN"), "{error}");
        }
        _ => {}
    });
    let (_, puck) = host.find::<RigidBody>("puck").unwrap();
    assert!(
        (puck.linear_velocity.x - 2.0).abs() < 1e-3,
        "v = J/m = 2 m/s, got {}",
        puck.linear_velocity.x
    );
    let (_, spun) = host.find::<RigidBody>("spun").unwrap();
    assert!(
        (spun.linear_velocity - Vec3::new(0.0, 0.0, 3.0)).length() < 1e-3,
        "{:?}",
        spun.linear_velocity
    );
    assert!((spun.angular_velocity.y - 1.0).abs() < 1e-3);
}

#[test]
fn a_ball_lands_raises_a_contact_event_and_a_ray_finds_the_ground() {
    let hit = Arc::new(Mutex::new(None));
    let h = hit.clone();
    let (host, events) = run(90, move |ctx, frame| {
        if frame == 0 {
            ground(ctx);
            ctx.spawn((
                Name::new("ball"),
                Transform::from_xyz(0.0, 1.0, 0.0),
                RigidBody::dynamic(),
                Collider::sphere(0.25),
            ))
            .unwrap();
        }
        if frame == 80 {
            *h.lock().unwrap() = ctx.raycast(Vec3::new(3.0, 5.0, 0.0), Vec3::NEG_Y, 100.0);
        }
    });
    let (ball, t) = host.find::<Transform>("ball").unwrap();
    assert!(
        (t.translation.y - 0.25).abs() < 0.01,
        "the ball rests on the ground: {}",
        t.translation.y
    );
    let (ground, _) = host.find::<Transform>("ground").unwrap();
    let started: Vec<_> = events
        .iter()
        .filter(|e| matches!(e, PhysicsEvent::ContactStarted { .. }))
        .collect();
    assert!(!started.is_empty(), "no contact event: {events:?}");
    let PhysicsEvent::ContactStarted { a, b, normal, .. } = started[0] else {
        unreachable!()
    };
    assert!(
        [*a, *b].contains(&ball) && [*a, *b].contains(&ground),
        "{started:?}"
    );
    assert!(normal.y.abs() > 0.99, "the normal is vertical: {normal:?}");
    let hit = hit.lock().unwrap().expect("the ray hits the ground");
    assert_eq!(hit.entity, ground);
    assert!(
        (hit.distance - 5.0).abs() < 1e-3 && hit.normal.y > 0.99,
        "{hit:?}"
    );
}

#[test]
fn every_contact_start_has_an_end_when_bodies_part_or_vanish() {
    let (_, events) = run(120, |ctx, frame| {
        if frame == 0 {
            ground(ctx);
            ctx.spawn((
                Name::new("ball"),
                Transform::from_xyz(0.0, 0.6, 0.0),
                RigidBody::dynamic(),
                Collider::sphere(0.5),
            ))
            .unwrap();
        }
        if frame == 60 {
            let ball = ctx
                .entities()
                .to_vec()
                .into_iter()
                .find(|e| ctx.get::<Name>(*e).is_ok_and(|n| n.as_str() == "ball"))
                .unwrap();
            ctx.despawn(ball).unwrap();
        }
    });
    let starts = events
        .iter()
        .filter(|e| matches!(e, PhysicsEvent::ContactStarted { .. }))
        .count();
    let ends = events
        .iter()
        .filter(|e| matches!(e, PhysicsEvent::ContactEnded { .. }))
        .count();
    assert!(starts >= 1);
    assert_eq!(starts, ends, "{events:?}");
}

#[test]
fn moving_the_transform_teleports_the_body_and_axis_locks_hold() {
    let (host, _) = run(40, |ctx, frame| {
        if frame == 0 {
            let locked = RigidBody::dynamic().with_locked_axes(LockedAxes::TRANSLATION_Y);
            ctx.spawn((
                Name::new("hover"),
                Transform::from_xyz(0.0, 3.0, 0.0),
                locked,
                Collider::sphere(0.5),
            ))
            .unwrap();
            ctx.spawn((
                Name::new("jumper"),
                Transform::from_xyz(0.0, 50.0, 0.0),
                RigidBody::dynamic(),
                Collider::sphere(0.5),
            ))
            .unwrap();
        }
        if frame == 20 {
            let jumper = ctx
                .entities()
                .to_vec()
                .into_iter()
                .find(|e| ctx.get::<Name>(*e).is_ok_and(|n| n.as_str() == "jumper"))
                .unwrap();
            ctx.set(jumper, Transform::from_xyz(10.0, 200.0, 0.0))
                .unwrap();
        }
    });
    let (_, hover) = host.find::<Transform>("hover").unwrap();
    assert_eq!(hover.translation.y, 3.0, "a Y-locked body does not fall");
    let (_, jumper) = host.find::<Transform>("jumper").unwrap();
    assert!(
        jumper.translation.x == 10.0 && jumper.translation.y > 195.0,
        "teleported: {:?}",
        jumper.translation
    );
}

#[test]
fn invalid_physics_components_are_refused() {
    run(1, |ctx, _| {
        let e = ctx.spawn(Transform::IDENTITY).unwrap();
        assert!(ctx.set(e, Collider::sphere(-1.0)).is_err());
        assert!(ctx.set(e, Collider::sphere(f32::NAN)).is_err());
        let mut body = RigidBody::dynamic();
        body.linear_velocity = Vec3::INFINITY;
        assert!(ctx.set(e, body).is_err());
        assert!(ctx.set(e, RigidBody::dynamic().with_mass(-2.0)).is_err());
        let hull = Collider::new(onyx_plugin_api::ColliderShape::ConvexHull {
            mesh: onyx_plugin_api::MeshId(999),
        });
        assert!(ctx.set(e, hull).is_err(), "a hull needs a loaded model");
        assert!(ctx.apply_force(e, Vec3::X).is_err(), "no collider, no body");
    });
}

#[test]
fn a_hull_from_a_model_falls_and_rests_and_a_missing_model_is_reported_once() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let events = Arc::new(Mutex::new(Vec::new()));
    let e = events.clone();
    struct Watcher(Arc<Mutex<Vec<String>>>);
    impl Plugin for Watcher {
        fn on_event(&mut self, _: &mut Ctx, event: &Event) {
            if let Event::Graphics(g) = event {
                self.0.lock().unwrap().push(format!("{g:?}"));
            }
        }
    }
    let mut host = HeadlessHost::with_config(onyx_runtime::HostConfig::default().asset_root(root));
    host.add_plugin("watcher", Watcher(e)).unwrap();
    let spawner = Scripted {
        script: Box::new(|ctx, frame| {
            if frame == 0 {
                ground(ctx);
                let vase = ctx.load_mesh("assets/models/vase/vase.obj").unwrap();
                let hull = Collider::new(onyx_plugin_api::ColliderShape::ConvexHull { mesh: vase });
                ctx.spawn((
                    Name::new("vase"),
                    Transform::from_xyz(0.0, 2.0, 0.0),
                    RigidBody::dynamic(),
                    hull,
                ))
                .unwrap();
                let missing = ctx.load_mesh("assets/models/missing.obj").unwrap();
                let bad =
                    Collider::new(onyx_plugin_api::ColliderShape::ConvexHull { mesh: missing });
                ctx.spawn((
                    Name::new("ghost"),
                    Transform::from_xyz(3.0, 2.0, 0.0),
                    RigidBody::dynamic(),
                    bad,
                ))
                .unwrap();
            }
        }),
        frame: 0,
        events: Arc::new(Mutex::new(Vec::new())),
    };
    host.add_plugin("spawner", spawner).unwrap();
    host.step(240);
    let (_, vase) = host.find::<RigidBody>("vase").unwrap();
    assert!(
        vase.grounded && vase.linear_velocity.length() < 0.05,
        "the vase came to rest: {vase:?}"
    );
    let (_, t) = host.find::<Transform>("vase").unwrap();
    // The vase's origin is the middle of its foot: resting on the ground puts it at y = 0.
    assert!(
        t.translation.y.abs() < 0.01,
        "resting on its foot on the ground, not through it: {}",
        t.translation.y
    );
    let failures: Vec<String> = events
        .lock()
        .unwrap()
        .iter()
        .filter(|e| e.contains("AssetFailed"))
        .cloned()
        .collect();
    assert_eq!(failures.len(), 1, "{failures:?}");
    assert!(failures[0].contains("missing.obj"), "{failures:?}");
    let (_, ghost) = host.find::<Transform>("ghost").unwrap();
    assert_eq!(
        ghost.translation.y, 2.0,
        "no collider, no body: it does not move"
    );
}

/// A trigger zone: a ball falls through a sensor box as through air (free fall, exactly) and
/// the zone's entity gets one `SensorEntered` and one `SensorExited` naming the ball; no
/// contact event, and the ground the ball lands on below still raises its own.
#[test]
fn a_ball_falls_through_a_trigger_zone_which_reports_it_entering_and_leaving() {
    let (host, events) = run(150, |ctx, frame| {
        if frame == 0 {
            ground(ctx);
            ctx.spawn((
                Name::new("zone"),
                Transform::from_xyz(0.0, 5.0, 0.0),
                RigidBody::fixed(),
                Collider::cuboid(1.0, 1.0, 1.0).with_sensor(true),
            ))
            .unwrap();
            ctx.spawn((
                Name::new("ball"),
                Transform::from_xyz(0.0, 10.0, 0.0),
                RigidBody::dynamic(),
                Collider::sphere(0.25),
            ))
            .unwrap();
        }
    });
    let (ball, _) = host.find::<Transform>("ball").unwrap();
    let (zone, _) = host.find::<Transform>("zone").unwrap();
    let (ground, _) = host.find::<Transform>("ground").unwrap();
    let sensor_events: Vec<_> = events
        .iter()
        .filter(|e| {
            matches!(
                e,
                PhysicsEvent::SensorEntered { .. } | PhysicsEvent::SensorExited { .. }
            )
        })
        .copied()
        .collect();
    assert_eq!(
        sensor_events,
        vec![
            PhysicsEvent::SensorEntered {
                sensor: zone,
                other: ball
            },
            PhysicsEvent::SensorExited {
                sensor: zone,
                other: ball
            },
        ],
        "{events:?}"
    );
    // Only the ground touched the ball.
    for e in &events {
        if let PhysicsEvent::ContactStarted { a, b, .. } = e {
            assert!([*a, *b].contains(&ground), "a contact with the zone: {e:?}");
        }
    }
    // It fell the whole 10 m − r to the ground: nothing in the zone held it.
    let (_, t) = host.find::<Transform>("ball").unwrap();
    assert!(
        (t.translation.y - 0.25).abs() < 0.01,
        "ball at {}",
        t.translation
    );
}
