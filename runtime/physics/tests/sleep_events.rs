//! Sleeping, waking, contact events and pair lifetime, grounded flag, NaN quarantine, CCD.
mod common;
use common::*;
use onyx_physics::glam::Vec3;
use onyx_physics::{ColliderDesc, ContactEventKind, PhysicsSettings, PhysicsWorld, RigidBodyDesc};
use std::collections::HashMap;

#[test]
fn resting_box_sleeps_and_wakes_when_hit() {
    let (mut w, _) = world_with_ground(0.5);
    let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, 0.5, 0.0)));
    w.insert_collider(ColliderDesc::cuboid(0.5, 0.5, 0.5), b);
    run(&mut w, 90);
    assert!(
        w.body(b).unwrap().is_sleeping(),
        "box at rest for 1.5 s should sleep (time_to_sleep 0.5 s)"
    );
    let x0 = w.body(b).unwrap().translation().x;
    // Fire a ball at it.
    let ball = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(-3.0, 0.5, 0.0))
            .linvel(Vec3::X * 8.0),
    );
    w.insert_collider(ColliderDesc::sphere(0.25).density(4000.0), ball);
    let mut woke = false;
    for _ in 0..60 {
        w.step();
        woke |= !w.body(b).unwrap().is_sleeping();
    }
    let dx = w.body(b).unwrap().translation().x - x0;
    assert!(woke, "hit box never woke");
    assert!(dx > 0.05, "hit box moved {dx} m, expected > 0.05");
}

#[test]
fn user_force_wakes_sleeping_body() {
    let (mut w, _) = world_with_ground(0.5);
    let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, 0.5, 0.0)));
    w.insert_collider(ColliderDesc::cuboid(0.5, 0.5, 0.5), b);
    run(&mut w, 90);
    assert!(w.body(b).unwrap().is_sleeping());
    w.body_mut(b).unwrap().add_force(Vec3::Y * 30_000.0);
    w.step();
    let body = w.body(b).unwrap();
    assert!(!body.is_sleeping(), "force must wake the body");
    assert!(
        body.linvel().y > 0.0,
        "upward force must lift: vy = {}",
        body.linvel().y
    );
}

#[test]
fn contact_events_pair_up_every_start_has_an_end() {
    let (mut w, g) = world_with_ground(0.5);
    let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, 2.0, 0.0)));
    let c = w
        .insert_collider(ColliderDesc::sphere(0.25).restitution(0.7), b)
        .unwrap();
    let mut open: HashMap<(u64, u64), usize> = HashMap::new();
    let mut starts = 0;
    let check = |events: &[onyx_physics::ContactEvent],
                 open: &mut HashMap<(u64, u64), usize>,
                 starts: &mut usize| {
        for e in events {
            let key = (
                e.collider_a.0.min(e.collider_b.0),
                e.collider_a.0.max(e.collider_b.0),
            );
            let n = open.entry(key).or_default();
            match e.kind {
                ContactEventKind::Started => {
                    assert_eq!(*n, 0, "second start without end for {key:?}");
                    *n = 1;
                    *starts += 1;
                    assert!(e.impulse > 0.0, "start impulse {} should be > 0", e.impulse);
                    let up = if e.body_b == b {
                        e.normal.y
                    } else {
                        -e.normal.y
                    };
                    assert!(up > 0.99, "normal toward ball {:?}, expected +Y", e.normal);
                    assert!(!e.points.is_empty());
                    assert!(e.body_a == g || e.body_b == g);
                }
                ContactEventKind::Ended => {
                    assert_eq!(*n, 1, "end without start for {key:?}");
                    *n = 0;
                }
            }
        }
    };
    for _ in 0..240 {
        let out = w.step();
        check(&out.events, &mut open, &mut starts);
    }
    assert!(
        starts >= 2,
        "bouncing ball should start touching several times, got {starts}"
    );
    w.remove_collider(c);
    let out = w.step();
    check(&out.events, &mut open, &mut starts);
    assert!(
        open.values().all(|&n| n == 0),
        "unmatched starts after removal: {open:?}"
    );
}

#[test]
fn grounded_flag_and_last_contact_normal() {
    let (mut w, _) = world_with_ground(0.5);
    let b = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(0.0, 3.0, 0.0))
            .can_sleep(false),
    );
    w.insert_collider(ColliderDesc::cuboid(0.5, 0.5, 0.5), b);
    w.step();
    assert!(
        !w.body(b).unwrap().is_grounded(),
        "falling box is not grounded"
    );
    run(&mut w, 120);
    let body = w.body(b).unwrap();
    assert!(body.is_grounded(), "resting box is grounded");
    let n = body
        .last_contact_normal()
        .expect("resting box has a contact normal");
    assert!(
        (n - Vec3::Y).length() < 1e-3,
        "last normal {n}, expected +Y"
    );
}

#[test]
fn nan_force_quarantines_body_and_others_are_unaffected() {
    let mut w = PhysicsWorld::default();
    let bad = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, 10.0, 0.0)));
    w.insert_collider(ColliderDesc::sphere(0.5), bad);
    let good = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.6, 10.0, 0.0)));
    w.insert_collider(ColliderDesc::sphere(0.5), good);
    run(&mut w, 10);
    let bad_pose = w.body(bad).unwrap().translation();
    w.body_mut(bad)
        .unwrap()
        .add_force(Vec3::new(f32::NAN, 0.0, 0.0));
    let out = w.step();
    assert_eq!(out.quarantined, vec![bad], "quarantined list");
    run(&mut w, 50);
    let bb = w.body(bad).unwrap();
    assert!(bb.is_quarantined());
    assert!(
        bb.translation().is_finite() && (bb.translation() - bad_pose).length() < 1e-6,
        "rolled back to {bad_pose}, is {}",
        bb.translation()
    );
    let g = w.body(good).unwrap();
    assert!(
        g.translation().is_finite() && g.linvel().is_finite(),
        "NaN spread to neighbour"
    );
    let t = 61.0 / 60.0;
    let expected_v = -G * t;
    assert!(
        (g.linvel().y - expected_v).abs() < 0.02,
        "neighbour vy {}, expected free fall {expected_v}",
        g.linvel().y
    );
}

fn shoot_at_wall(ccd: bool) -> (f32, u32) {
    let s = PhysicsSettings {
        gravity: Vec3::ZERO,
        ..Default::default()
    };
    let mut w = PhysicsWorld::new(s);
    let wall = w.insert_body(RigidBodyDesc::fixed().translation(Vec3::new(5.0, 0.0, 0.0)));
    w.insert_collider(ColliderDesc::cuboid(0.025, 2.0, 2.0), wall); // 5 cm thick
    let b = w.insert_body(
        RigidBodyDesc::dynamic()
            .linvel(Vec3::X * 300.0)
            .ccd_enabled(ccd),
    );
    w.insert_collider(ColliderDesc::sphere(0.005), b); // 1 cm sphere
    let mut max_x = f32::MIN;
    let mut toi_hits = 0;
    for _ in 0..60 {
        toi_hits += w.step().counters.ccd_hits;
        max_x = max_x.max(w.body(b).unwrap().translation().x);
    }
    (max_x, toi_hits)
}

#[test]
fn ccd_one_cm_sphere_at_300_mps_does_not_pass_5_cm_wall() {
    let wall_front = 5.0 - 0.025;
    let (x, toi_hits) = shoot_at_wall(true);
    assert!(
        x < wall_front,
        "with CCD the sphere reached x = {x}, wall front at {wall_front}"
    );
    assert!(
        toi_hits >= 1,
        "the time-of-impact sweep should have clamped the first step"
    );
    // Without CCD the same shot tunnels (the scenario really needs CCD).
    let (x_no, _) = shoot_at_wall(false);
    assert!(
        x_no > 5.025,
        "without CCD expected tunnelling, sphere max x = {x_no}"
    );
}

/// A pair lives exactly while the two fat boxes overlap: a ball thrown up off a box loses
/// its pair once it has left the box's bounds (its proxy moved out of its fat box, so the
/// overlap is tested again), and gets one back when it lands.
#[test]
fn a_pair_lives_while_fat_boxes_overlap() {
    let mut w = PhysicsWorld::new(PhysicsSettings::default());
    let g = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(ColliderDesc::cuboid(2.0, 0.5, 2.0), g)
        .unwrap();
    let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, 0.75, 0.0)));
    w.insert_collider(ColliderDesc::sphere(0.25), b).unwrap();
    run(&mut w, 30);
    assert_eq!(w.step().counters.pairs, 1, "the resting ball has one pair");

    w.body_mut(b).unwrap().set_linvel(Vec3::new(0.0, 10.0, 0.0));
    let mut fewest = u32::MAX;
    let mut steps_alone = 0;
    for _ in 0..240 {
        let pairs = w.step().counters.pairs;
        fewest = fewest.min(pairs);
        steps_alone += u32::from(pairs == 0);
    }
    assert_eq!(fewest, 0, "the pair outlived the overlap of the fat boxes");
    assert!(
        steps_alone > 60,
        "only {steps_alone} steps without a pair in a ~2 s flight"
    );
    let y = w.body(b).unwrap().translation().y;
    assert!(
        (y - 0.75).abs() < 0.01,
        "the ball lands back on the box (y = {y})"
    );
    assert_eq!(
        w.step().counters.pairs,
        1,
        "the landed ball has its pair again"
    );
}
