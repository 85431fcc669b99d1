//! Shapes stretched by a scale (`Shape::scaled`): sizes, volumes and surfaces follow the
//! scale; round shapes stay round and say so; a mirrored mesh still faces out.
mod common;
use common::*;
use onyx_physics::glam::Vec3;
use onyx_physics::shape::Shape;
use onyx_physics::{ColliderDesc, RigidBodyDesc};

fn cube_points() -> Vec<Vec3> {
    let mut p = Vec::new();
    for x in [-0.5, 0.5] {
        for y in [-0.5, 0.5] {
            for z in [-0.5, 0.5] {
                p.push(Vec3::new(x, y, z));
            }
        }
    }
    p
}

#[test]
fn a_scaled_box_and_hull_have_the_scaled_extents_and_volume() {
    let scale = Vec3::new(2.0, -3.0, 0.5);
    let cuboid = ColliderDesc::cuboid(0.5, 0.5, 0.5);
    let (desc, made_uniform) = cuboid.scaled(scale).unwrap();
    assert!(!made_uniform);
    let mut w = onyx_physics::PhysicsWorld::default();
    let b = w.insert_body(RigidBodyDesc::fixed());
    let c = w.insert_collider(desc, b).unwrap();
    match w.collider(c).unwrap().shape() {
        Shape::Cuboid(c) => assert_eq!(c.half_extents, Vec3::new(1.0, 1.5, 0.25)),
        other => panic!("a box stays a box: {other:?}"),
    }
    let hull = Shape::ConvexHull(std::sync::Arc::new(
        onyx_physics::shape::ConvexHull::from_points(&cube_points()).unwrap(),
    ));
    let scaled = hull.scaled(scale).unwrap();
    assert!(!scaled.made_uniform);
    // Volume |sx sy sz| · 1 m³; with density 1 the mass is the volume.
    let mass = scaled.shape.mass_properties(1.0).mass;
    assert!((mass - 3.0).abs() < 1e-4, "hull mass {mass}, expected 3");
    let bounds = scaled.shape.aabb(&onyx_physics::Pose::IDENTITY);
    assert!(
        (bounds.half_extents() - Vec3::new(1.0, 1.5, 0.25))
            .abs()
            .max_element()
            < 1e-5,
        "{bounds:?}"
    );
}

#[test]
fn spheres_and_capsules_stay_round_under_a_non_uniform_scale_and_say_so() {
    let sphere = Shape::Sphere(onyx_physics::shape::Sphere { radius: 0.5 });
    let uniform = sphere.scaled(Vec3::splat(-2.0)).unwrap();
    assert!(!uniform.made_uniform);
    assert_eq!(
        uniform.shape,
        Shape::Sphere(onyx_physics::shape::Sphere { radius: 1.0 })
    );
    let stretched = sphere.scaled(Vec3::new(1.0, 3.0, 1.0)).unwrap();
    assert!(stretched.made_uniform, "a stretched sphere is reported");
    assert_eq!(
        stretched.shape,
        Shape::Sphere(onyx_physics::shape::Sphere { radius: 1.5 })
    );
    let capsule = Shape::Capsule(onyx_physics::shape::Capsule {
        half_height: 1.0,
        radius: 0.25,
    });
    let c = capsule.scaled(Vec3::new(2.0, 1.0, 1.0)).unwrap();
    assert!(c.made_uniform);
    assert_eq!(
        c.shape,
        Shape::Capsule(onyx_physics::shape::Capsule {
            half_height: 2.0,
            radius: 0.5
        })
    );
}

#[test]
fn a_mirrored_mesh_still_faces_out_and_a_box_rests_on_it_at_the_scaled_height() {
    // A 2 × 2 floor made of two triangles at y = 0.5, facing up; scaled by (-3, 2, 3) (a
    // mirror in x): the floor is at y = 1, 6 × 6 m, and must still face up.
    let vertices = vec![
        Vec3::new(-1.0, 0.5, -1.0),
        Vec3::new(1.0, 0.5, -1.0),
        Vec3::new(1.0, 0.5, 1.0),
        Vec3::new(-1.0, 0.5, 1.0),
    ];
    let triangles = vec![[0, 2, 1], [0, 3, 2]];
    let (desc, _) = ColliderDesc::trimesh(vertices, triangles)
        .unwrap()
        .scaled(Vec3::new(-3.0, 2.0, 3.0))
        .unwrap();
    let mut w = onyx_physics::PhysicsWorld::default();
    let floor = w.insert_body(RigidBodyDesc::fixed());
    let fc = w.insert_collider(desc, floor).unwrap();
    let Shape::TriMesh(mesh) = w.collider(fc).unwrap().shape().clone() else {
        panic!("a mesh stays a mesh");
    };
    let [a, b, c] = mesh.triangle(0);
    let normal = (b - a).cross(c - a).normalize();
    assert!(normal.y > 0.99, "the mirrored floor faces {normal}");
    let cube = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(2.5, 2.0, 0.0)));
    w.insert_collider(ColliderDesc::cuboid(0.25, 0.25, 0.25), cube);
    run(&mut w, 180);
    let y = w.body(cube).unwrap().translation().y;
    assert!(
        (y - 1.25).abs() < 0.01,
        "the box rests on the floor at y = 1 (centre 1.25), it is at {y}; it is past the \
         unscaled floor's edge at x = 1"
    );
}

/// A sphere spawned at the centre of a box was thought to get no contact: the sphere–box
/// test pushes it out through the nearest face.
#[test]
fn a_sphere_spawned_at_a_boxs_centre_is_pushed_out_through_the_nearest_face() {
    let mut w = onyx_physics::PhysicsWorld::new(onyx_physics::PhysicsSettings {
        gravity: Vec3::ZERO,
        ..Default::default()
    });
    let block = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(ColliderDesc::cuboid(2.0, 0.5, 2.0), block);
    let ball = w.insert_body(RigidBodyDesc::dynamic());
    w.insert_collider(ColliderDesc::sphere(0.25), ball);
    let mut started = false;
    for _ in 0..120 {
        started |= w
            .step()
            .events
            .iter()
            .any(|e| e.kind == onyx_physics::ContactEventKind::Started);
    }
    assert!(started, "a contact started between the ball and the block");
    let y = w.body(ball).unwrap().translation().y.abs();
    assert!(
        y >= 0.75 - 0.02,
        "the ball left through the top or bottom face (|y| ≥ 0.75), it is at |y| = {y}"
    );
}
