//! Stacking stability: column of boxes and a 20-row pyramid.
mod common;
use common::*;
use onyx_physics::glam::Vec3;
use onyx_physics::{BodyHandle, ColliderDesc, PhysicsWorld, RigidBodyDesc};

fn drift(w: &PhysicsWorld, b: BodyHandle, p0: Vec3) -> f32 {
    (w.body(b).unwrap().translation() - p0).length()
}

#[test]
fn ten_box_stack_rests_1000_steps_with_top_drift_below_1cm() {
    let (mut w, _) = world_with_ground(0.6);
    // Sleeping off: the solver alone must hold the stack.
    w.settings_mut().sleep_enabled = false;
    let h = 0.5;
    let mut boxes = Vec::new();
    for i in 0..10 {
        let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(
            0.0,
            h + 2.0 * h * i as f32,
            0.0,
        )));
        w.insert_collider(ColliderDesc::cuboid(h, h, h).friction(0.6), b);
        boxes.push(b);
    }
    let top = *boxes.last().unwrap();
    run(&mut w, 60); // settle into contact (slop)
    let p0 = w.body(top).unwrap().translation();
    run(&mut w, 1000);
    let d = drift(&w, top, p0);
    assert!(
        d < 0.01,
        "top box drift over 1000 steps: {d} m, expected < 0.01"
    );
    let y = w.body(top).unwrap().translation().y;
    let expected = h + 2.0 * h * 9.0;
    assert!(
        (y - expected).abs() < 0.05,
        "top height {y}, expected {expected} ± 0.05 (stack must not sink)"
    );
}

#[test]
fn twenty_row_pyramid_of_210_boxes_stands_1000_steps() {
    let (mut w, _) = world_with_ground(0.6);
    w.settings_mut().sleep_enabled = false;
    let h = 0.5;
    let rows = 20;
    let mut boxes = Vec::new();
    for row in 0..rows {
        let n = rows - row;
        for i in 0..n {
            let x = (i as f32 - (n - 1) as f32 * 0.5) * 2.0 * h * 1.02;
            let y = h + row as f32 * 2.0 * h;
            let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(x, y, 0.0)));
            w.insert_collider(ColliderDesc::cuboid(h, h, h).friction(0.6), b);
            boxes.push((b, Vec3::new(x, y, 0.0)));
        }
    }
    assert_eq!(boxes.len(), 210);
    run(&mut w, 1000);
    let mut worst = 0.0f32;
    for (b, p0) in &boxes {
        worst = worst.max(drift(&w, *b, *p0));
    }
    let (top, top0) = boxes.last().unwrap();
    let top_drop = top0.y - w.body(*top).unwrap().translation().y;
    assert!(
        worst < 0.1,
        "largest box displacement {worst} m, expected < 0.1 (pyramid stands)"
    );
    assert!(top_drop < 0.1, "apex sank {top_drop} m, expected < 0.1");
}

#[test]
fn five_box_stack_at_1e5_m_offset_rests_like_at_origin() {
    // Offsets of 1e5 m: f32 position resolution is ~8 mm there; contacts are computed
    // relative to the bodies, so the stack must behave as at the origin.
    let offset = Vec3::new(1.0e5, 0.0, -1.0e5);
    let mut w = PhysicsWorld::default();
    w.settings_mut().sleep_enabled = false;
    let g = w.insert_body(RigidBodyDesc::fixed().translation(offset + Vec3::new(0.0, -0.5, 0.0)));
    w.insert_collider(ColliderDesc::cuboid(5.0, 0.5, 5.0), g);
    let h = 0.5;
    let mut top = None;
    for i in 0..5 {
        let b = w.insert_body(
            RigidBodyDesc::dynamic()
                .translation(offset + Vec3::new(0.0, h + 2.0 * h * i as f32, 0.0)),
        );
        w.insert_collider(ColliderDesc::cuboid(h, h, h), b);
        top = Some(b);
    }
    let top = top.unwrap();
    run(&mut w, 60);
    let p0 = w.body(top).unwrap().translation();
    run(&mut w, 500);
    let d = drift(&w, top, p0);
    assert!(
        d < 0.01,
        "far stack top drift {d} m over 500 steps, expected < 0.01"
    );
    let y = w.body(top).unwrap().translation().y;
    assert!(
        (y - 4.5).abs() < 0.05,
        "far stack top height {y}, expected 4.5 ± 0.05"
    );
}

/// A frictionless stack with its middle box 10 cm off centre is in equilibrium (every box's
/// weight is over its support) and must stay so: nothing but the contact normals acts
/// sideways, so a normal that follows the few-µm tilt of a loaded compliant contact would
/// push the boxes downhill and apart (they used to slide off each other within ~50 s).
#[test]
fn frictionless_offset_stack_holds_still_for_4000_steps() {
    let (mut w, _) = world_with_ground(0.0);
    w.settings_mut().sleep_enabled = false;
    let h = 0.5;
    let mut boxes = Vec::new();
    for i in 0..3 {
        let x = if i == 1 { 0.1 } else { 0.0 };
        let p = Vec3::new(x, h + 2.0 * h * i as f32, 0.0);
        let b = w.insert_body(RigidBodyDesc::dynamic().translation(p));
        w.insert_collider(ColliderDesc::cuboid(h, h, h).friction(0.0), b);
        boxes.push((b, p));
    }
    run(&mut w, 4000);
    for (i, &(b, p0)) in boxes.iter().enumerate() {
        let p = w.body(b).unwrap().translation();
        let sideways = Vec3::new(p.x - p0.x, 0.0, p.z - p0.z).length();
        assert!(
            sideways < 1e-3,
            "box {i} moved {sideways} m sideways over 4000 frictionless steps, expected < 1 mm"
        );
        assert!(
            (p.y - p0.y).abs() < 0.01,
            "box {i} height {} (start {})",
            p.y,
            p0.y
        );
    }
}

#[test]
fn a_column_of_twenty_balls_stiffens_its_loaded_contacts() {
    // Soft contacts at the balanced preset's 32 Hz would let the lowest pair, carrying 19
    // balls through an effective mass of half a ball, press 9.2 mm together (2 · 19 g / ω²);
    // ball pairs stiffen with their load up to 60 Hz at 60 × 4, which leaves 2.6 mm.
    let (mut w, _) = world_with_ground(0.5);
    let r = 0.1;
    let balls: Vec<BodyHandle> = (0..20)
        .map(|i| {
            let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(
                0.0,
                r + 2.0 * r * i as f32,
                0.0,
            )));
            w.insert_collider(ColliderDesc::sphere(r), b);
            b
        })
        .collect();
    run(&mut w, 240);
    let y = |k: usize| w.body(balls[k]).unwrap().translation().y;
    let lowest_pair = 2.0 * r - (y(1) - y(0));
    assert!(
        (0.0..0.004).contains(&lowest_pair),
        "the two lowest balls press {lowest_pair:.5} m together"
    );
    for (k, &b) in balls.iter().enumerate() {
        let p = w.body(b).unwrap().translation();
        assert!(
            p.x.abs() < 1e-3 && p.z.abs() < 1e-3,
            "ball {k} left the column: {p}"
        );
    }
}
