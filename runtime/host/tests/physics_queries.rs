//! What a plugin asks of physics through `Ctx` besides forces and rays: overlap queries
//! (exact, filtered), shape casts, a joint's coordinate and the event of a joint breaking,
//! and moving a kinematic character — checked against geometry and free fall.

use std::sync::{Arc, Mutex};

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::{
    CharacterController, Collider, ColliderShape, Ctx, CtxError, Entity, Event, Flow, Joint,
    JointTarget, Name, PhysicsEvent, Plugin, QueryFilter, RigidBody, Transform,
};
use onyx_runtime::HeadlessHost;

type Script = Box<dyn FnMut(&mut Ctx, u64) + Send>;

/// Runs a closure in each fixed step with the step number; records physics events.
struct Scripted {
    script: Script,
    step: u64,
    events: Arc<Mutex<Vec<PhysicsEvent>>>,
}

impl Plugin for Scripted {
    fn on_event(&mut self, _: &mut Ctx, event: &Event) {
        if let Event::Physics(e) = event {
            self.events.lock().unwrap().push(*e);
        }
    }
    fn on_fixed_update(&mut self, ctx: &mut Ctx) {
        (self.script)(ctx, self.step);
        self.step += 1;
    }
    fn on_update(&mut self, _: &mut Ctx, _: f32) -> Flow {
        Flow::Continue
    }
}

fn run(
    steps: u32,
    script: impl FnMut(&mut Ctx, u64) + Send + 'static,
) -> (HeadlessHost, Vec<PhysicsEvent>) {
    let events = Arc::new(Mutex::new(Vec::new()));
    let mut host = HeadlessHost::new();
    let plugin = Scripted {
        script: Box::new(script),
        step: 0,
        events: events.clone(),
    };
    host.add_plugin("scripted", plugin).unwrap();
    host.step(steps);
    let events = events.lock().unwrap().clone();
    (host, events)
}

fn spawn_box(ctx: &mut Ctx, name: &str, at: Vec3, collider: Collider) -> Entity {
    ctx.spawn((
        Name::new(name),
        Transform::from_translation(at),
        RigidBody::fixed(),
        collider,
    ))
    .unwrap()
}

#[test]
fn overlap_finds_exactly_the_colliders_a_shape_touches_and_shape_casts_meet_the_first() {
    let seen = Arc::new(Mutex::new(Vec::new()));
    let out = seen.clone();
    run(3, move |ctx, step| {
        if step == 0 {
            spawn_box(ctx, "a", Vec3::ZERO, Collider::cuboid(0.5, 0.5, 0.5));
            spawn_box(
                ctx,
                "b",
                Vec3::new(3.0, 0.0, 0.0),
                Collider::cuboid(0.5, 0.5, 0.5),
            );
            spawn_box(
                ctx,
                "zone",
                Vec3::new(6.0, 0.0, 0.0),
                Collider::cuboid(0.5, 0.5, 0.5).with_sensor(true),
            );
            return;
        }
        if step != 2 {
            return;
        }
        let sphere = ColliderShape::Sphere { radius: 0.6 };
        let all = QueryFilter::default();
        let mut report = Vec::new();
        // Into b's face at x = 2.5 by 5 cm.
        report.push(ctx.overlap(sphere, Transform::from_xyz(1.95, 0.0, 0.0), &all));
        // Off a's corner: inside its bounding box's reach, 0.73 m from the corner.
        report.push(ctx.overlap(sphere, Transform::from_xyz(1.0, 1.0, 1.0), &all));
        // Everything along the row, then without sensors and without a.
        let long = ColliderShape::Box {
            half_extents: [4.0, 0.1, 0.1],
        };
        report.push(ctx.overlap(long, Transform::from_xyz(3.0, 0.0, 0.0), &all));
        let a = ctx.entities().to_vec();
        let a = *a
            .iter()
            .find(|e| ctx.get::<Name>(**e).is_ok_and(|n| n.0 == "a"))
            .unwrap();
        let solid = QueryFilter::default().without_sensors().excluding(a);
        report.push(ctx.overlap(long, Transform::from_xyz(3.0, 0.0, 0.0), &solid));
        // A unit cube scaled 2.2x wide at x = 1.5 reaches a (x ≤ 0.5) and b (x ≥ 2.5).
        let cube = ColliderShape::Box {
            half_extents: [0.5, 0.5, 0.5],
        };
        let wide = Transform::from_xyz(1.5, 0.0, 0.0).with_scale(Vec3::new(2.2, 1.0, 1.0));
        report.push(ctx.overlap(cube, wide, &all));
        let cast = ctx.shape_cast(
            sphere,
            Transform::from_xyz(-5.0, 0.0, 0.0),
            Vec3::X,
            20.0,
            &all,
        );
        let past_a = ctx.shape_cast(
            sphere,
            Transform::from_xyz(-5.0, 0.0, 0.0),
            Vec3::X,
            20.0,
            &QueryFilter::default().excluding(a),
        );
        let plane = ctx.overlap(ColliderShape::Plane, Transform::IDENTITY, &all);
        out.lock().unwrap().push((report, cast, past_a, plane));
    });
    let seen = seen.lock().unwrap();
    let (report, cast, past_a, plane) = &seen[0];
    let counts: Vec<usize> = report
        .iter()
        .map(|r| r.as_ref().expect("a valid query").len())
        .collect();
    assert_eq!(
        counts,
        vec![1, 0, 3, 1, 2],
        "touching b; not the corner of a; a, b and the zone; b alone; a and b: {report:?}"
    );
    let hit = cast.as_ref().unwrap().expect("a is in the way");
    assert!(
        (hit.distance - (5.0 - 0.5 - 0.6)).abs() < 1e-3,
        "the sphere meets a's face after 3.9 m: {hit:?}"
    );
    assert!(hit.normal.distance(Vec3::NEG_X) < 1e-3, "{hit:?}");
    let next = past_a.as_ref().unwrap().expect("b is next");
    assert!(
        (next.distance - (8.0 - 0.5 - 0.6)).abs() < 1e-3,
        "past a, it meets b after 6.9 m: {next:?}"
    );
    assert!(
        matches!(plane, Err(CtxError::Invalid { .. })),
        "a plane is refused: {plane:?}"
    );
}

#[test]
fn a_slider_reads_its_free_fall_and_a_weld_past_its_strength_reports_breaking() {
    let readings = Arc::new(Mutex::new(Vec::new()));
    let out = readings.clone();
    let (host, events) = run(61, move |ctx, step| {
        if step == 0 {
            // A slider along Y to the world: the body falls freely along it.
            let slider = Joint::prismatic(JointTarget::World, [0.0, 1.0, 0.0])
                .with_anchors([0.0; 3], [0.0, 10.0, 0.0]);
            ctx.spawn((
                Name::new("slider"),
                Transform::from_xyz(0.0, 10.0, 0.0),
                RigidBody::dynamic(),
                Collider::sphere(0.1),
                slider,
            ))
            .unwrap();
            // 10 kg (≈ 98 N) on a weld that holds 50 N.
            let weld = Joint::fixed(JointTarget::World)
                .with_anchors([0.0; 3], [5.0, 10.0, 0.0])
                .with_break(50.0, 0.0);
            ctx.spawn((
                Name::new("weld"),
                Transform::from_xyz(5.0, 10.0, 0.0),
                RigidBody::dynamic().with_mass(10.0),
                Collider::sphere(0.1),
                weld,
            ))
            .unwrap();
            return;
        }
        let slider = ctx
            .entities()
            .to_vec()
            .into_iter()
            .find(|e| ctx.get::<Name>(*e).is_ok_and(|n| n.0 == "slider"))
            .unwrap();
        out.lock()
            .unwrap()
            .push((ctx.time().ticks, ctx.joint_coordinate(slider)));
    });
    let readings = readings.lock().unwrap();
    // The joint is made in the first step; the last reading follows 60 steps (1 s) of
    // sliding, g/2 down (semi-implicit Euler adds n(n+1)/n² − 1 ≈ 1.7 %).
    let (_, last) = readings.last().unwrap();
    let y = last.as_ref().unwrap().expect("a slider has a position");
    let t = 1.0;
    let expected = -0.5 * 9.81 * t * t;
    assert!(
        (y - expected).abs() < 0.03 * expected.abs(),
        "the slider reads {y} m, free fall says {expected}"
    );
    let (weld, joint) = host.find::<Joint>("weld").unwrap();
    assert!(joint.broken);
    let broke: Vec<_> = events
        .iter()
        .filter_map(|e| match e {
            PhysicsEvent::JointBroke { entity, force, .. } => Some((*entity, *force)),
            _ => None,
        })
        .collect();
    assert_eq!(broke.len(), 1, "one JointBroke: {events:?}");
    assert_eq!(broke[0].0, weld);
    assert!(
        broke[0].1.length() > 50.0,
        "it broke carrying more than its 50 N: {}",
        broke[0].1
    );
}

#[test]
fn a_kinematic_character_walks_to_a_wall_and_a_dynamic_one_is_refused() {
    let results = Arc::new(Mutex::new(Vec::new()));
    let out = results.clone();
    let (host, _) = run(60, move |ctx, step| {
        if step == 0 {
            ctx.spawn((Name::new("ground"), Transform::IDENTITY, Collider::plane()))
                .unwrap();
            spawn_box(
                ctx,
                "wall",
                Vec3::new(2.0, 1.0, 0.0),
                Collider::cuboid(0.5, 1.0, 5.0),
            );
            ctx.spawn((
                Name::new("walker"),
                Transform::from_xyz(0.0, 0.81, 0.0),
                RigidBody::kinematic(),
                Collider::capsule(0.5, 0.3),
            ))
            .unwrap();
            ctx.spawn((
                Name::new("ball"),
                Transform::from_xyz(0.0, 5.0, 5.0),
                RigidBody::dynamic(),
                Collider::sphere(0.3),
            ))
            .unwrap();
            return;
        }
        let find = |ctx: &mut Ctx, name: &str| {
            ctx.entities()
                .to_vec()
                .into_iter()
                .find(|e| ctx.get::<Name>(*e).is_ok_and(|n| n.0 == name))
                .unwrap()
        };
        let walker = find(ctx, "walker");
        let ball = find(ctx, "ball");
        let walked = ctx.move_character(
            walker,
            Vec3::new(0.05, -0.01, 0.0),
            &CharacterController::default(),
        );
        let refused = ctx.move_character(ball, Vec3::X, &CharacterController::default());
        out.lock().unwrap().push((walked, refused.is_err()));
    });
    let results = results.lock().unwrap();
    let (last, refused) = results.last().unwrap();
    let last = last.as_ref().expect("the walker moves");
    assert!(*refused, "a dynamic body is not a character");
    assert!(last.grounded);
    let (wall, _) = host.find::<Transform>("wall").unwrap();
    assert!(
        last.collisions.iter().any(|c| c.entity == wall),
        "it runs into the wall: {last:?}"
    );
    let (_, t) = host.find::<Transform>("walker").unwrap();
    assert!(
        (t.translation.x - (1.5 - 0.3 - 0.01)).abs() < 3e-3
            && (t.translation.y - 0.81).abs() < 3e-3,
        "the walker stands at the wall: {}",
        t.translation
    );
}
