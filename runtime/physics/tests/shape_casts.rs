//! Shape casts (`PhysicsWorld::cast_shape`) against shapes with known answers: distances,
//! normals and points of first contact, starts in overlap, and the filter.
mod common;
use common::*;
use onyx_physics::glam::{Quat, Vec3};
use onyx_physics::shape::{Cuboid, Shape, Sphere};
use onyx_physics::{ColliderDesc, Pose, QueryFilter, RigidBodyDesc};

const FRAC_1_SQRT_2: f32 = std::f32::consts::FRAC_1_SQRT_2;

#[test]
fn a_ball_cast_down_meets_the_ground_at_its_height_less_its_radius() {
    let (mut w, ground) = world_with_ground(0.5);
    w.step();
    let ball = Shape::Sphere(Sphere { radius: 0.5 });
    let hit = w
        .cast_shape(
            &ball,
            &Pose::new(Vec3::new(3.0, 5.0, -2.0), Quat::IDENTITY),
            Vec3::new(0.0, -2.0, 0.0),
            10.0,
            0.0,
            &QueryFilter::default(),
        )
        .expect("the ground is below");
    assert_eq!(hit.body, ground);
    assert!(
        (hit.distance - 4.5).abs() < 1e-3,
        "distance {}",
        hit.distance
    );
    assert!(hit.normal.distance(Vec3::Y) < 1e-4, "normal {}", hit.normal);
    assert!(
        hit.point.distance(Vec3::new(3.0, 0.0, -2.0)) < 1e-3,
        "point {}",
        hit.point
    );
    assert!(hit.converged);
    // With a gap of 0.1 it stops 0.1 short; too short a cast meets nothing.
    let pose = Pose::new(Vec3::new(3.0, 5.0, -2.0), Quat::IDENTITY);
    let f = QueryFilter::default();
    let gap = w
        .cast_shape(&ball, &pose, Vec3::NEG_Y, 10.0, 0.1, &f)
        .unwrap();
    assert!(
        (gap.distance - 4.4).abs() < 1e-3,
        "distance {}",
        gap.distance
    );
    assert!(w
        .cast_shape(&ball, &pose, Vec3::NEG_Y, 4.0, 0.0, &f)
        .is_none());
}

#[test]
fn a_box_cast_at_a_turned_box_meets_its_corner() {
    let mut w = onyx_physics::PhysicsWorld::default();
    // A 2 m cube turned 45° about Y at x = 5: its nearest edge at x = 5 − √2.
    let b = w.insert_body(
        RigidBodyDesc::fixed()
            .translation(Vec3::new(5.0, 0.0, 0.0))
            .rotation(Quat::from_rotation_y(std::f32::consts::FRAC_PI_4)),
    );
    w.insert_collider(ColliderDesc::cuboid(1.0, 1.0, 1.0), b);
    w.step();
    let cube = Shape::Cuboid(Cuboid {
        half_extents: Vec3::splat(0.5),
    });
    let hit = w
        .cast_shape(
            &cube,
            &Pose::IDENTITY,
            Vec3::X,
            20.0,
            0.0,
            &QueryFilter::default(),
        )
        .expect("the turned box is ahead");
    let expected = 5.0 - std::f32::consts::SQRT_2 - 0.5;
    assert!(
        (hit.distance - expected).abs() < 1e-3,
        "distance {}, expected {expected}",
        hit.distance
    );
    assert!((hit.point.x - (5.0 - std::f32::consts::SQRT_2)).abs() < 1e-3);
    // The edge meets a face: the normal is the caster's face's, −x, or a face of the turned
    // box (±45°); either way it faces back along the cast.
    assert!(
        hit.normal.x <= -FRAC_1_SQRT_2 + 1e-3,
        "normal {}",
        hit.normal
    );
}

#[test]
fn a_cast_out_of_an_overlap_is_free_and_one_further_in_hits_at_once() {
    let mut w = onyx_physics::PhysicsWorld::default();
    let b = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(ColliderDesc::cuboid(1.0, 1.0, 1.0), b);
    w.step();
    let ball = Shape::Sphere(Sphere { radius: 0.5 });
    let pose = Pose::new(Vec3::new(1.2, 0.0, 0.0), Quat::IDENTITY);
    let f = QueryFilter::default();
    assert!(w.cast_shape(&ball, &pose, Vec3::X, 5.0, 0.0, &f).is_none());
    let hit = w
        .cast_shape(&ball, &pose, Vec3::NEG_X, 5.0, 0.0, &f)
        .unwrap();
    assert_eq!(hit.distance, 0.0);
    // Sliding along the face does not stop it either.
    let touching = Pose::new(Vec3::new(1.5, 0.0, 0.0), Quat::IDENTITY);
    assert!(w
        .cast_shape(&ball, &touching, Vec3::Y, 5.0, 0.0, &f)
        .is_none());
}

#[test]
fn the_filter_skips_sensors_groups_and_the_excluded_body() {
    let (mut w, ground) = world_with_ground(0.5);
    let zone = w.insert_body(RigidBodyDesc::fixed().translation(Vec3::new(0.0, 2.0, 0.0)));
    w.insert_collider(ColliderDesc::cuboid(1.0, 0.5, 1.0).sensor(true), zone);
    let roof = w.insert_body(RigidBodyDesc::fixed().translation(Vec3::new(0.0, 4.0, 0.0)));
    w.insert_collider(
        ColliderDesc::cuboid(1.0, 0.1, 1.0)
            .collision_groups(onyx_physics::CollisionGroups::new(2, u32::MAX)),
        roof,
    );
    w.step();
    let ball = Shape::Sphere(Sphere { radius: 0.25 });
    let pose = Pose::new(Vec3::new(0.0, 6.0, 0.0), Quat::IDENTITY);
    let cast = |f: QueryFilter| {
        w.cast_shape(&ball, &pose, Vec3::NEG_Y, 10.0, 0.0, &f)
            .map(|h| h.body)
    };
    assert_eq!(cast(QueryFilter::default()), Some(roof));
    let past_roof = QueryFilter {
        groups: Some(onyx_physics::CollisionGroups::new(1, !2)),
        ..QueryFilter::default()
    };
    assert_eq!(cast(past_roof), Some(zone));
    let solid = QueryFilter {
        exclude_sensors: true,
        exclude_body: Some(roof),
        ..QueryFilter::default()
    };
    assert_eq!(cast(solid), Some(ground));
}
