mod common;
use common::*;
use onyx_physics::glam::Vec3;
use onyx_physics::{ColliderDesc, RigidBodyDesc};

#[test]
fn sphere_and_box_come_to_rest_on_ground() {
    let (mut w, _) = world_with_ground(0.5);
    let s = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, 2.0, 0.0)));
    w.insert_collider(ColliderDesc::sphere(0.5), s);
    let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(3.0, 2.0, 0.0)));
    w.insert_collider(ColliderDesc::cuboid(0.5, 0.5, 0.5), b);
    for i in 0..240 {
        w.step();
        if i % 20 == 0 {
            let bs = w.body(s).unwrap();
            let bb = w.body(b).unwrap();
            println!(
                "{i}: sphere y={:.4} v={:.3}  box y={:.4} v={:.3}",
                bs.translation().y,
                bs.linvel().y,
                bb.translation().y,
                bb.linvel().y
            );
        }
    }
    let ys = w.body(s).unwrap().translation().y;
    let yb = w.body(b).unwrap().translation().y;
    assert!(
        (ys - 0.5).abs() < 0.01,
        "sphere rest height {ys} expected 0.5 ± 0.01"
    );
    assert!(
        (yb - 0.5).abs() < 0.01,
        "box rest height {yb} expected 0.5 ± 0.01"
    );
}
