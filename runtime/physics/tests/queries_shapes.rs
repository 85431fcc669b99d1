//! Scene queries and non-box shapes in simulation (capsule, convex hull, triangle mesh).
mod common;
use common::*;
use onyx_physics::glam::{Quat, Vec3};
use onyx_physics::shape::{Shape, Sphere};
use onyx_physics::{Aabb, ColliderDesc, PhysicsWorld, Pose, QueryFilter, RigidBodyDesc};

#[test]
fn raycast_closest_and_all_hits_match_geometry() {
    let (mut w, ground) = world_with_ground(0.5);
    let s = w.insert_body(RigidBodyDesc::fixed().translation(Vec3::new(0.0, 2.0, 0.0)));
    w.insert_collider(ColliderDesc::sphere(1.0), s);
    let b = w.insert_body(
        RigidBodyDesc::fixed()
            .translation(Vec3::new(5.0, 1.0, 0.0))
            .rotation(Quat::from_rotation_y(std::f32::consts::FRAC_PI_4)),
    );
    w.insert_collider(ColliderDesc::cuboid(1.0, 1.0, 1.0), b);
    let c = w.insert_body(RigidBodyDesc::fixed().translation(Vec3::new(-5.0, 3.0, 0.0)));
    w.insert_collider(ColliderDesc::capsule(1.0, 0.5), c);
    w.step();
    let f = QueryFilter::default();
    let hit = w
        .cast_ray(Vec3::new(0.0, 10.0, 0.0), Vec3::NEG_Y, 100.0, &f)
        .expect("hit sphere");
    assert_eq!(hit.body, s);
    assert!(
        (hit.toi - 7.0).abs() < 1e-4,
        "sphere toi {}, expected 7",
        hit.toi
    );
    assert!((hit.normal - Vec3::Y).length() < 1e-4);
    let all = w.cast_ray_all(Vec3::new(0.0, 10.0, 0.0), Vec3::NEG_Y, 100.0, &f);
    let tois: Vec<f32> = all.iter().map(|h| h.toi).collect();
    assert_eq!(all.len(), 2, "sphere and ground: {tois:?}");
    assert!(
        (tois[1] - 10.0).abs() < 1e-4 && all[1].body == ground,
        "ground toi {tois:?}"
    );
    // Box turned 45°: the corner sticks out by √2.
    let hit = w
        .cast_ray(Vec3::new(15.0, 1.0, 0.0), Vec3::NEG_X, 100.0, &f)
        .expect("hit box");
    let expected = 10.0 - 2f32.sqrt();
    assert!(
        (hit.toi - expected).abs() < 1e-4,
        "box toi {}, expected {expected}",
        hit.toi
    );
    // Capsule side and cap.
    let hit = w
        .cast_ray(Vec3::new(-15.0, 3.5, 0.0), Vec3::X, 100.0, &f)
        .unwrap();
    assert!(
        (hit.toi - 9.5).abs() < 1e-4,
        "capsule side toi {}, expected 9.5",
        hit.toi
    );
    let hit = w
        .cast_ray(Vec3::new(-5.0, 10.0, 0.0), Vec3::NEG_Y, 100.0, &f)
        .unwrap();
    assert!(
        (hit.toi - 5.5).abs() < 1e-4,
        "capsule cap toi {}, expected 5.5",
        hit.toi
    );
    // Filter excludes the sphere.
    let hit = w
        .cast_ray(
            Vec3::new(0.0, 10.0, 0.0),
            Vec3::NEG_Y,
            100.0,
            &QueryFilter {
                exclude_body: Some(s),
                ..Default::default()
            },
        )
        .unwrap();
    assert_eq!(hit.body, ground);
}

#[test]
fn shape_and_aabb_overlap_queries() {
    let mut w = PhysicsWorld::default();
    let s = w.insert_body(RigidBodyDesc::fixed().translation(Vec3::new(0.0, 2.0, 0.0)));
    let cs = w.insert_collider(ColliderDesc::sphere(1.0), s).unwrap();
    let b = w.insert_body(RigidBodyDesc::fixed().translation(Vec3::new(4.0, 0.0, 0.0)));
    let cb = w
        .insert_collider(ColliderDesc::cuboid(1.0, 1.0, 1.0), b)
        .unwrap();
    w.step();
    let f = QueryFilter::default();
    let probe = Shape::Sphere(Sphere { radius: 0.5 });
    assert_eq!(
        w.intersect_shape(
            &probe,
            &Pose::from_translation(Vec3::new(0.0, 3.4, 0.0)),
            &f
        ),
        vec![cs],
        "1.4 < 1.5: overlap"
    );
    assert!(
        w.intersect_shape(
            &probe,
            &Pose::from_translation(Vec3::new(0.0, 3.6, 0.0)),
            &f
        )
        .is_empty(),
        "1.6 > 1.5: apart"
    );
    assert_eq!(
        w.intersect_shape(
            &probe,
            &Pose::from_translation(Vec3::new(5.4, 0.0, 0.0)),
            &f
        ),
        vec![cb]
    );
    assert!(w
        .intersect_shape(
            &probe,
            &Pose::from_translation(Vec3::new(5.6, 0.0, 0.0)),
            &f
        )
        .is_empty());
    let mut hits = w.intersect_aabb(
        &Aabb::new(Vec3::new(-1.0, -1.0, -1.0), Vec3::new(3.5, 1.5, 1.0)),
        &f,
    );
    hits.sort();
    let mut expected = vec![cs, cb];
    expected.sort();
    assert_eq!(hits, expected);
    assert!(w
        .intersect_aabb(&Aabb::new(Vec3::splat(10.0), Vec3::splat(11.0)), &f)
        .is_empty());
}

#[test]
fn capsule_rests_lying_and_standing_at_radius_heights() {
    let (mut w, _) = world_with_ground(0.6);
    let (hh, r) = (0.5, 0.2);
    let lying = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(0.0, 1.0, 0.0))
            .rotation(Quat::from_rotation_z(std::f32::consts::FRAC_PI_2)),
    );
    w.insert_collider(ColliderDesc::capsule(hh, r), lying);
    let standing = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(3.0, 1.0, 0.0))
            .lock_rotations(),
    );
    w.insert_collider(ColliderDesc::capsule(hh, r), standing);
    run(&mut w, 180);
    let y1 = w.body(lying).unwrap().translation().y;
    let y2 = w.body(standing).unwrap().translation().y;
    assert!(
        (y1 - r).abs() < 0.01,
        "lying capsule height {y1}, expected r = {r} ± 0.01"
    );
    assert!(
        (y2 - (hh + r)).abs() < 0.01,
        "standing capsule height {y2}, expected {} ± 0.01",
        hh + r
    );
    let up = w.body(lying).unwrap().rotation() * Vec3::Y;
    assert!(
        up.y.abs() < 0.05,
        "lying capsule should stay lying, axis {up}"
    );
}

#[test]
fn capsule_rests_flat_on_box_via_gjk_clipping() {
    let mut w = PhysicsWorld::default();
    let table = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(ColliderDesc::cuboid(2.0, 0.5, 2.0), table);
    let cap = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(0.0, 1.0, 0.0))
            .rotation(Quat::from_rotation_x(std::f32::consts::FRAC_PI_2)),
    );
    w.insert_collider(ColliderDesc::capsule(0.6, 0.25), cap);
    run(&mut w, 180);
    let b = w.body(cap).unwrap();
    let y = b.translation().y;
    assert!(
        (y - 0.75).abs() < 0.01,
        "capsule on box at {y}, expected 0.75 ± 0.01"
    );
    assert!(
        b.angvel().length() < 0.05 && b.linvel().length() < 0.05,
        "capsule should rest"
    );
}

#[test]
fn convex_hull_box_rests_on_triangle_mesh_ground() {
    let mut w = PhysicsWorld::default();
    let ground = w.insert_body(RigidBodyDesc::fixed());
    let s = 20.0;
    let verts = vec![
        Vec3::new(-s, 0.0, -s),
        Vec3::new(s, 0.0, -s),
        Vec3::new(s, 0.0, s),
        Vec3::new(-s, 0.0, s),
    ];
    w.insert_collider(
        ColliderDesc::trimesh(verts, vec![[0, 2, 1], [0, 3, 2]]).unwrap(),
        ground,
    );
    let h = Vec3::new(0.4, 0.3, 0.5);
    let pts = onyx_physics::shape::Cuboid { half_extents: h }.vertices();
    let hull = w.insert_body(
        RigidBodyDesc::dynamic()
            .translation(Vec3::new(1.0, 1.5, 0.5))
            .rotation(Quat::from_rotation_y(0.4)),
    );
    w.insert_collider(ColliderDesc::convex_hull(&pts).unwrap(), hull);
    let ball = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(-2.0, 1.0, 0.0)));
    w.insert_collider(ColliderDesc::sphere(0.3), ball);
    let mut epa_fail = 0;
    for _ in 0..240 {
        epa_fail += w.step().counters.epa_failures;
    }
    let y = w.body(hull).unwrap().translation().y;
    assert!(
        (y - h.y).abs() < 0.01,
        "hull box height {y}, expected {} ± 0.01",
        h.y
    );
    let yb = w.body(ball).unwrap().translation().y;
    assert!(
        (yb - 0.3).abs() < 0.01,
        "ball on mesh height {yb}, expected 0.3 ± 0.01"
    );
    let up = w.body(hull).unwrap().rotation() * Vec3::Y;
    assert!(up.y > 0.999, "hull should rest flat, up = {up}");
    assert_eq!(epa_fail, 0, "EPA failures while resting");
}

#[test]
fn debug_lines_cover_colliders_and_contacts() {
    let (mut w, _) = world_with_ground(0.5);
    let b = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, 0.5, 0.0)));
    w.insert_collider(ColliderDesc::cuboid(0.5, 0.5, 0.5), b);
    run(&mut w, 10);
    let mut lines = Vec::new();
    w.debug_lines_into(&mut lines, true, false);
    // Plane: 4 edges + normal; box: 12 edges.
    assert_eq!(lines.len(), 5 + 12);
    let all = w.debug_lines();
    let contacts = all.len() - lines.len();
    assert_eq!(
        contacts,
        4 * 4,
        "4 contact points × (3 cross lines + 1 normal)"
    );
    // Box edges (after the plane, inserted first) lie on the box.
    for l in &lines[5..] {
        for p in [l.a, l.b] {
            let local = p - w.body(b).unwrap().translation();
            assert!((local.abs().max_element() - 0.5).abs() < 1e-4);
        }
    }
}

#[test]
fn capsule_pairs_overlap_exactly_at_radius_sum() {
    use onyx_physics::shape::Capsule;
    let mut w = PhysicsWorld::default();
    let (hh, r) = (1.0, 0.3);
    let c = w.insert_body(
        RigidBodyDesc::fixed().rotation(Quat::from_rotation_z(std::f32::consts::FRAC_PI_2)),
    );
    let cc = w.insert_collider(ColliderDesc::capsule(hh, r), c).unwrap();
    w.step();
    let f = QueryFilter::default();
    let probe = Shape::Capsule(Capsule {
        half_height: 0.5,
        radius: 0.2,
    });
    let crossed = Quat::from_rotation_x(std::f32::consts::FRAC_PI_2);
    let sum = r + 0.2;
    for (y, expect) in [(sum - 0.01, true), (sum + 0.01, false)] {
        let hits = w.intersect_shape(&probe, &Pose::new(Vec3::new(0.3, y, 0.0), crossed), &f);
        assert_eq!(
            !hits.is_empty(),
            expect,
            "crossed capsules at y = {y} (radius sum {sum})"
        );
    }
    // Parallel capsules side by side, and a sphere near the cap.
    let parallel = Quat::from_rotation_z(std::f32::consts::FRAC_PI_2);
    for (z, expect) in [(sum - 0.01, true), (sum + 0.01, false)] {
        let hits = w.intersect_shape(&probe, &Pose::new(Vec3::new(0.8, 0.0, z), parallel), &f);
        assert_eq!(!hits.is_empty(), expect, "parallel capsules at z = {z}");
    }
    let ball = Shape::Sphere(Sphere { radius: 0.1 });
    for (x, expect) in [(hh + r + 0.09, true), (hh + r + 0.11, false)] {
        let hits = w.intersect_shape(&ball, &Pose::from_translation(Vec3::new(x, 0.0, 0.0)), &f);
        assert_eq!(hits == vec![cc], expect, "sphere at cap x = {x}");
    }
}

#[test]
fn teleported_static_body_is_found_by_queries_at_its_new_place() {
    let mut w = PhysicsWorld::default();
    let s = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(ColliderDesc::sphere(1.0), s);
    w.step();
    w.body_mut(s)
        .unwrap()
        .set_translation(Vec3::new(50.0, 0.0, 0.0));
    w.step();
    let f = QueryFilter::default();
    let hit = w
        .cast_ray(Vec3::new(50.0, 10.0, 0.0), Vec3::NEG_Y, 100.0, &f)
        .expect("hit at new place");
    assert!((hit.toi - 9.0).abs() < 1e-4, "toi {}, expected 9", hit.toi);
    assert!(
        w.cast_ray(Vec3::new(0.0, 10.0, 0.0), Vec3::NEG_Y, 100.0, &f)
            .is_none(),
        "old place must be empty"
    );
}

#[test]
fn debug_lines_mark_a_joints_anchors_where_the_joint_holds_them_together() {
    let mut w = PhysicsWorld::default();
    let bob = w.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(1.0, 5.0, 0.0)));
    w.insert_collider(ColliderDesc::sphere(0.1), bob);
    let pivot = Vec3::new(0.0, 5.0, 0.0);
    w.insert_joint(
        onyx_physics::JointDesc::spherical()
            .local_anchor_a(pivot)
            .local_anchor_b(Vec3::new(-1.0, 0.0, 0.0)),
        None,
        bob,
    )
    .unwrap();
    run(&mut w, 30);
    let mut lines = Vec::new();
    w.debug_lines_into(&mut lines, true, false);
    let joint: Vec<_> = lines
        .iter()
        .filter(|l| l.color == onyx_physics::debug_lines::colors::JOINT)
        .collect();
    // Two crosses (3 lines each), the segment between the anchors, the axis.
    assert_eq!(joint.len(), 8, "{joint:?}");
    let s = onyx_physics::debug_lines::DEBUG_JOINT_ANCHOR_SIZE;
    for cross in joint[..6].iter() {
        let centre = (cross.a + cross.b) * 0.5;
        assert!(
            centre.distance(pivot) < 0.01,
            "every cross is at the pivot (the swinging bob's anchor stays on it): {centre}"
        );
        assert!((cross.a.distance(cross.b) - 2.0 * s).abs() < 1e-5);
    }
}
