//! Sensors: a ball falling through a sensor zone falls exactly as in an empty world (bit for
//! bit), and the zone reports one start when the ball first overlaps it and one end when it
//! has left, in the step after the one its own trajectory crosses each face in; nothing is grounded by a sensor and a fast
//! CCD body is not stopped by one.

mod common;

use onyx_physics::glam::Vec3;
use onyx_physics::{
    BodyHandle, ColliderDesc, ContactEventKind, PhysicsSettings, PhysicsWorld, RigidBodyDesc,
};

const RADIUS: f32 = 0.25;
/// The zone: a 2 m cube centred at y = 5 (top 6, bottom 4).
const ZONE_TOP: f32 = 6.0;
const ZONE_BOTTOM: f32 = 4.0;

fn world(with_zone: bool) -> (PhysicsWorld, BodyHandle) {
    let mut w = PhysicsWorld::new(PhysicsSettings {
        sleep_enabled: false,
        ..PhysicsSettings::default()
    });
    if with_zone {
        let zone = w.insert_body(RigidBodyDesc::fixed().translation(Vec3::new(0.0, 5.0, 0.0)));
        w.insert_collider(ColliderDesc::cuboid(1.0, 1.0, 1.0).sensor(true), zone);
    }
    let ball = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, 10.0, 0.0)));
    w.insert_collider(ColliderDesc::sphere(RADIUS), ball);
    (w, ball)
}

#[test]
fn a_ball_falls_through_a_sensor_as_through_air_and_is_reported_entering_and_leaving() {
    let (mut free, free_ball) = world(false);
    let (mut w, ball) = world(true);
    let (mut started, mut ended) = (Vec::new(), Vec::new());
    let (mut first_overlap, mut first_clear) = (None, None);
    for step in 0..120 {
        free.step();
        let out = w.step();
        for e in &out.events {
            assert!(e.sensor, "a contact event that is not a sensor's: {e:?}");
            match e.kind {
                ContactEventKind::Started => started.push(step),
                ContactEventKind::Ended => ended.push(step),
            }
        }
        let b = w.body(ball).unwrap();
        assert_eq!(
            b.translation(),
            free.body(free_ball).unwrap().translation(),
            "step {step}: the sensor changed the fall"
        );
        assert!(!b.is_grounded(), "a sensor grounded the ball");
        let y = b.translation().y;
        if first_overlap.is_none() && y - RADIUS < ZONE_TOP {
            first_overlap = Some(step);
        }
        if first_overlap.is_some() && first_clear.is_none() && y + RADIUS < ZONE_BOTTOM {
            first_clear = Some(step);
        }
    }
    // One start and one end. Overlap is found from the poses a step starts from, so a step
    // that moves the ball into (out of) the zone is followed by the step that reports it.
    assert_eq!(started, vec![first_overlap.unwrap() + 1], "starts");
    assert_eq!(ended.len(), 1, "ends: {ended:?}");
    let clear = first_clear.unwrap();
    assert!(
        ended[0] == clear + 1,
        "ended at step {}, the ball left in step {clear}",
        ended[0]
    );
}

#[test]
fn a_fast_ccd_body_is_not_stopped_by_a_thin_sensor() {
    let mut w = PhysicsWorld::new(PhysicsSettings {
        gravity: Vec3::ZERO,
        ..PhysicsSettings::default()
    });
    let sheet = w.insert_body(RigidBodyDesc::fixed().translation(Vec3::new(5.0, 0.0, 0.0)));
    w.insert_collider(ColliderDesc::cuboid(0.01, 2.0, 2.0).sensor(true), sheet);
    let bullet = w.insert_body(
        RigidBodyDesc::dynamic()
            .linvel(Vec3::new(500.0, 0.0, 0.0))
            .ccd_enabled(true),
    );
    w.insert_collider(ColliderDesc::sphere(0.05), bullet);
    for _ in 0..2 {
        w.step();
    }
    let b = w.body(bullet).unwrap();
    assert_eq!(b.linvel(), Vec3::new(500.0, 0.0, 0.0));
    assert!(
        (b.translation().x - 1000.0 / 60.0).abs() < 1e-3,
        "at {}",
        b.translation()
    );
}
