//! Collision groups: a bullet that ignores its shooter flies through it at its launch speed
//! and stops on the wall behind; either side's filter can refuse a pair; queries honour the
//! groups they are given.

mod common;

use onyx_physics::glam::Vec3;
use onyx_physics::{
    BodyHandle, ColliderDesc, CollisionGroups, PhysicsSettings, PhysicsWorld, QueryFilter,
    RigidBodyDesc,
};

const SHOOTER: u32 = 1 << 0;
const BULLETS: u32 = 1 << 1;
const WORLD: u32 = 1 << 2;

/// A shooter box at the origin, a wall at x = 5, a bullet fired from 0.4 m behind the
/// shooter's back face at 10 m/s along +X, through the shooter (no gravity). Returns the world, the bullet and the shooter.
fn range(
    bullet: CollisionGroups,
    shooter: CollisionGroups,
) -> (PhysicsWorld, BodyHandle, BodyHandle) {
    let mut w = PhysicsWorld::new(PhysicsSettings {
        gravity: Vec3::ZERO,
        sleep_enabled: false,
        ..PhysicsSettings::default()
    });
    let wall = w.insert_body(RigidBodyDesc::fixed().translation(Vec3::new(5.0, 0.0, 0.0)));
    w.insert_collider(
        ColliderDesc::cuboid(0.5, 2.0, 2.0).collision_groups(CollisionGroups::new(WORLD, u32::MAX)),
        wall,
    );
    let s = w.insert_body(RigidBodyDesc::dynamic());
    w.insert_collider(
        ColliderDesc::cuboid(0.5, 0.5, 0.5).collision_groups(shooter),
        s,
    );
    let b = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(-1.0, 0.0, 0.0))
            .linvel(Vec3::new(10.0, 0.0, 0.0)),
    );
    w.insert_collider(ColliderDesc::sphere(0.1).collision_groups(bullet), b);
    (w, b, s)
}

#[test]
fn a_bullet_that_ignores_its_shooter_passes_through_it_and_stops_on_the_wall() {
    let bullet = CollisionGroups::new(BULLETS, !SHOOTER);
    let shooter = CollisionGroups::new(SHOOTER, u32::MAX);
    let (mut w, b, s) = range(bullet, shooter);
    for _ in 0..20 {
        w.step();
    }
    // Still flying at 10 m/s after a third of a second inside and past the shooter.
    let v = w.body(b).unwrap().linvel();
    assert!((v.x - 10.0).abs() < 1e-4, "bullet slowed to {v}");
    assert!(
        w.body(s).unwrap().linvel().length() < 1e-6,
        "the shooter was pushed"
    );
    for _ in 0..60 {
        w.step();
    }
    // Stopped on the wall's face (x = 4.5) with its radius.
    let p = w.body(b).unwrap().translation();
    assert!(p.x < 4.5 - 0.1 + 0.01 && p.x > 4.0, "bullet at {p}");
}

#[test]
fn either_side_can_refuse_the_pair() {
    // The bullet accepts everything but the shooter's filter leaves out bullets.
    let (mut w, b, s) = range(
        CollisionGroups::new(BULLETS, u32::MAX),
        CollisionGroups::new(SHOOTER, !BULLETS),
    );
    w.step();
    assert!((w.body(b).unwrap().linvel().x - 10.0).abs() < 1e-4);
    assert!(w.body(s).unwrap().linvel().length() < 1e-6);
    // Both accept: the bullet hits the shooter.
    let (mut w, b, s) = range(CollisionGroups::ALL, CollisionGroups::ALL);
    for _ in 0..10 {
        w.step();
    }
    let dv = (w.body(b).unwrap().linvel() - Vec3::new(10.0, 0.0, 0.0)).length();
    let shooter = w.body(s).unwrap().linvel().length();
    assert!(
        dv > 0.1 && shooter > 1e-4,
        "no contact: bullet Δv {dv}, shooter {shooter}"
    );
}

#[test]
fn queries_honour_the_groups_they_are_given() {
    let (w, b, s) = range(
        CollisionGroups::new(BULLETS, !SHOOTER),
        CollisionGroups::new(SHOOTER, u32::MAX),
    );
    // From between the shooter and the wall, back toward the shooter.
    let origin = Vec3::new(3.0, 0.0, 0.0);
    let all = w
        .cast_ray(origin, Vec3::NEG_X, 100.0, &QueryFilter::default())
        .unwrap();
    assert_eq!(all.body, s);
    let past_shooters = QueryFilter {
        groups: Some(CollisionGroups::new(BULLETS, !SHOOTER)),
        ..Default::default()
    };
    let hit = w
        .cast_ray(origin, Vec3::NEG_X, 100.0, &past_shooters)
        .unwrap();
    // Past the shooter: the bullet behind it (its surface at x = -0.9).
    assert_eq!(hit.body, b, "the ray should skip the shooter");
    assert!((hit.toi - 3.9).abs() < 1e-3, "hit at {}", hit.toi);
}
