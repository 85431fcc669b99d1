//! GJK distance and EPA penetration against exact answers on seeded random poses,
//! including degenerate inputs (flat hulls, coincident faces, zero-size shapes).
mod common;
use common::*;
use onyx_physics::glam::{Mat3, Quat, Vec3};
use onyx_physics::narrowphase::epa::EPA_MAX_ITERATIONS;
use onyx_physics::narrowphase::gjk::GJK_MAX_ITERATIONS;
use onyx_physics::narrowphase::{epa_penetration, gjk_distance, EpaStatus, GjkStatus};
use onyx_physics::shape::{ConvexCore, ConvexHull, HullDimension};
use onyx_physics::Pose;

/// Exact distance from a point to a box (half extents `h` at `pose`), negative inside
/// (minus the distance to the nearest face).
fn point_box_signed_distance(p: Vec3, h: Vec3, pose: &Pose) -> f32 {
    let l = pose.inverse_transform_point(p);
    let q = l.abs() - h;
    let outside = q.max(Vec3::ZERO).length();
    let inside = q.max_element().min(0.0);
    outside + inside
}

/// Brute-force penetration depth of two boxes: the minimum overlap over the 15 SAT axes
/// (exact for polytopes). Negative when separated along some axis.
fn box_box_sat_depth(ha: Vec3, pa: &Pose, hb: Vec3, pb: &Pose) -> f32 {
    let ra = Mat3::from_quat(pa.rotation);
    let rb = Mat3::from_quat(pb.rotation);
    let aa = [ra.x_axis, ra.y_axis, ra.z_axis];
    let bb = [rb.x_axis, rb.y_axis, rb.z_axis];
    let mut axes: Vec<Vec3> = aa.iter().chain(bb.iter()).copied().collect();
    for a in aa {
        for b in bb {
            let c = a.cross(b);
            if c.length() > 1e-4 {
                axes.push(c.normalize());
            }
        }
    }
    let d = pb.translation - pa.translation;
    let mut best = f32::MAX;
    for n in axes {
        let ext_a: f32 = (0..3).map(|k| ha[k] * aa[k].dot(n).abs()).sum();
        let ext_b: f32 = (0..3).map(|k| hb[k] * bb[k].dot(n).abs()).sum();
        best = best.min(ext_a + ext_b - d.dot(n).abs());
    }
    best
}

#[test]
fn gjk_point_box_distance_matches_exact_on_random_poses() {
    let mut rng = Rng(7);
    let mut checked = 0;
    for _ in 0..500 {
        let h = rng.vec3(0.05, 2.0);
        let pose = Pose::new(rng.vec3(-5.0, 5.0), rng.quat());
        let p = rng.vec3(-8.0, 8.0);
        let exact = point_box_signed_distance(p, h, &pose);
        if exact <= 1e-3 {
            continue;
        }
        let r = gjk_distance(
            &ConvexCore::Point,
            &Pose::from_translation(p),
            &ConvexCore::Cuboid(h),
            &pose,
        );
        assert_eq!(r.status, GjkStatus::Separated);
        assert!(r.iterations <= GJK_MAX_ITERATIONS);
        assert!(
            (r.distance - exact).abs() < 1e-4 * exact.max(1.0),
            "point {p} box h {h}: GJK {} vs exact {exact}",
            r.distance
        );
        // Witness on the box surface.
        let on = point_box_signed_distance(r.point_b, h, &pose);
        assert!(on.abs() < 1e-4, "witness off the surface by {on}");
        checked += 1;
    }
    assert!(checked > 300);
}

#[test]
fn gjk_box_box_distance_matches_exact_for_parallel_boxes() {
    // Boxes sharing one random orientation: exact distance is the norm of per-axis gaps.
    let mut rng = Rng(11);
    for _ in 0..300 {
        let q = rng.quat();
        let (ha, hb) = (rng.vec3(0.1, 1.5), rng.vec3(0.1, 1.5));
        let local_offset = rng.vec3(-6.0, 6.0);
        let gap = (local_offset.abs() - ha - hb).max(Vec3::ZERO);
        let exact = gap.length();
        if exact < 1e-2 {
            continue;
        }
        let pa = Pose::new(rng.vec3(-3.0, 3.0), q);
        let pb = Pose::new(pa.translation + q * local_offset, q);
        let r = gjk_distance(&ConvexCore::Cuboid(ha), &pa, &ConvexCore::Cuboid(hb), &pb);
        assert!(
            (r.distance - exact).abs() < 2e-4 * exact.max(1.0),
            "GJK {} vs exact {exact} (status {:?}, {} iterations)",
            r.distance,
            r.status,
            r.iterations
        );
    }
}

#[test]
fn epa_point_in_box_depth_matches_distance_to_nearest_face() {
    let mut rng = Rng(3);
    for _ in 0..300 {
        let h = rng.vec3(0.2, 2.0);
        let pose = Pose::new(rng.vec3(-5.0, 5.0), rng.quat());
        let local = rng.vec3(-1.0, 1.0) * h * 0.95;
        let p = pose.transform_point(local);
        let exact = -point_box_signed_distance(p, h, &pose);
        let pp = Pose::from_translation(p);
        let g = gjk_distance(&ConvexCore::Point, &pp, &ConvexCore::Cuboid(h), &pose);
        assert_eq!(g.status, GjkStatus::Overlapping);
        let e = epa_penetration(
            &ConvexCore::Point,
            &pp,
            &ConvexCore::Cuboid(h),
            &pose,
            &g.simplex,
        );
        assert_ne!(e.status, EpaStatus::Degenerate);
        assert!(e.iterations <= EPA_MAX_ITERATIONS);
        assert!(
            (e.depth - exact).abs() < 1e-3 * exact.max(1.0),
            "EPA depth {} vs exact {exact}",
            e.depth
        );
        // Moving the point by depth along -normal (B→A reversed: B moves +n) separates.
        let moved = Pose::new(
            pose.translation + e.normal * (e.depth + 1e-3),
            pose.rotation,
        );
        assert!(
            point_box_signed_distance(p, h, &moved) > 0.0,
            "normal does not separate"
        );
    }
}

#[test]
fn epa_box_box_depth_matches_brute_force_sat() {
    let mut rng = Rng(5);
    let mut checked = 0;
    for _ in 0..400 {
        let (ha, hb) = (rng.vec3(0.2, 1.5), rng.vec3(0.2, 1.5));
        let pa = Pose::new(rng.vec3(-1.0, 1.0), rng.quat());
        let pb = Pose::new(pa.translation + rng.vec3(-1.2, 1.2), rng.quat());
        let exact = box_box_sat_depth(ha, &pa, hb, &pb);
        if exact < 1e-2 {
            continue;
        }
        let (a, b) = (ConvexCore::Cuboid(ha), ConvexCore::Cuboid(hb));
        let g = gjk_distance(&a, &pa, &b, &pb);
        assert_eq!(
            g.status,
            GjkStatus::Overlapping,
            "SAT says overlap by {exact}"
        );
        let e = epa_penetration(&a, &pa, &b, &pb, &g.simplex);
        assert_eq!(e.status, EpaStatus::Converged);
        assert!(
            (e.depth - exact).abs() < 2e-3 * exact.max(1.0),
            "EPA depth {} vs SAT {exact}",
            e.depth
        );
        checked += 1;
    }
    assert!(checked > 100, "only {checked} overlapping samples");
}

#[test]
fn degenerate_flat_hull_distance_matches_point_to_square() {
    let sq = [
        Vec3::new(-1.0, 0.0, -1.0),
        Vec3::new(1.0, 0.0, -1.0),
        Vec3::new(1.0, 0.0, 1.0),
        Vec3::new(-1.0, 0.0, 1.0),
        Vec3::ZERO,
    ];
    let hull = ConvexHull::from_points(&sq).unwrap();
    assert_eq!(hull.dimension(), HullDimension::Flat);
    assert_eq!(hull.vertices().len(), 4, "interior point dropped");
    let mut rng = Rng(9);
    for _ in 0..200 {
        let p = rng.vec3(-3.0, 3.0);
        let c = Vec3::new(p.x.clamp(-1.0, 1.0), 0.0, p.z.clamp(-1.0, 1.0));
        let exact = p.distance(c);
        let r = gjk_distance(
            &ConvexCore::Point,
            &Pose::from_translation(p),
            &ConvexCore::Hull(&hull),
            &Pose::IDENTITY,
        );
        if exact < 1e-3 {
            continue;
        }
        assert!(
            (r.distance - exact).abs() < 1e-4,
            "flat hull: GJK {} vs exact {exact}",
            r.distance
        );
    }
    // A point inside the flat square: EPA cannot expand a flat difference and must say so.
    let pp = Pose::from_translation(Vec3::new(0.2, 0.0, 0.3));
    let g = gjk_distance(
        &ConvexCore::Point,
        &pp,
        &ConvexCore::Hull(&hull),
        &Pose::IDENTITY,
    );
    assert_eq!(g.status, GjkStatus::Overlapping);
    let e = epa_penetration(
        &ConvexCore::Point,
        &pp,
        &ConvexCore::Hull(&hull),
        &Pose::IDENTITY,
        &g.simplex,
    );
    assert_eq!(
        e.status,
        EpaStatus::Degenerate,
        "flat Minkowski difference must be reported"
    );
    assert!(e.depth.is_finite() && e.normal.is_finite());
}

#[test]
fn degenerate_coincident_boxes_and_touching_faces() {
    let h = Vec3::new(0.5, 0.3, 0.8);
    let pose = Pose::new(Vec3::new(1.0, 2.0, 3.0), Quat::from_rotation_y(0.3));
    let c = ConvexCore::Cuboid(h);
    // Identical boxes: depth = 2 · smallest half extent.
    let g = gjk_distance(&c, &pose, &c, &pose);
    assert_eq!(g.status, GjkStatus::Overlapping);
    let e = epa_penetration(&c, &pose, &c, &pose, &g.simplex);
    assert_eq!(e.status, EpaStatus::Converged);
    assert!(
        (e.depth - 0.6).abs() < 1e-3,
        "coincident boxes depth {}, expected 0.6",
        e.depth
    );
    // Exactly touching faces: distance 0 within tolerance, no hang.
    let pb = Pose::new(
        pose.translation + pose.rotation * Vec3::new(1.0, 0.0, 0.0),
        pose.rotation,
    );
    let g = gjk_distance(&c, &pose, &c, &pb);
    assert!(g.iterations <= GJK_MAX_ITERATIONS);
    assert!(
        g.status == GjkStatus::Overlapping || g.distance < 1e-4,
        "touching faces: {:?} {}",
        g.status,
        g.distance
    );
}

#[test]
fn degenerate_zero_size_shapes() {
    let zero = ConvexCore::Cuboid(Vec3::ZERO);
    let a = Pose::from_translation(Vec3::new(1.0, 0.0, 0.0));
    let b = Pose::from_translation(Vec3::new(4.0, 4.0, 0.0));
    let r = gjk_distance(&zero, &a, &ConvexCore::Point, &b);
    assert!(
        (r.distance - 5.0).abs() < 1e-5,
        "zero box to point: {} expected 5",
        r.distance
    );
    // Two zero-size shapes at the same place: overlap, EPA reports degenerate, finite output.
    let g = gjk_distance(&zero, &a, &zero, &a);
    assert_eq!(g.status, GjkStatus::Overlapping);
    let e = epa_penetration(&zero, &a, &zero, &a, &g.simplex);
    assert_eq!(e.status, EpaStatus::Degenerate);
    assert!(e.depth.is_finite() && e.depth.abs() < 1e-6);
    // Single-point and two-point hulls.
    let p1 = ConvexHull::from_points(&[Vec3::ONE, Vec3::ONE]).unwrap();
    assert_eq!(p1.dimension(), HullDimension::Point);
    let seg = ConvexHull::from_points(&[Vec3::ZERO, Vec3::X, Vec3::X * 2.0]).unwrap();
    assert_eq!(seg.dimension(), HullDimension::Segment);
    let r = gjk_distance(
        &ConvexCore::Hull(&seg),
        &Pose::IDENTITY,
        &ConvexCore::Point,
        &Pose::from_translation(Vec3::new(1.0, 3.0, 0.0)),
    );
    assert!(
        (r.distance - 3.0).abs() < 1e-5,
        "segment hull distance {}",
        r.distance
    );
}

#[test]
fn hull_of_cube_cloud_has_six_faces_and_exact_mass() {
    let mut rng = Rng(1);
    let h = Vec3::new(0.5, 1.0, 1.5);
    let mut pts: Vec<Vec3> = onyx_physics::shape::Cuboid { half_extents: h }
        .vertices()
        .to_vec();
    for _ in 0..200 {
        pts.push(rng.vec3(-1.0, 1.0) * h);
    }
    let hull = ConvexHull::from_points(&pts).unwrap();
    assert_eq!(hull.vertices().len(), 8);
    assert_eq!(hull.faces().len(), 6);
    assert_eq!(hull.edges().len(), 12);
    let mp = hull.mass_properties(1000.0);
    let exact = onyx_physics::MassProperties::cuboid(1000.0, h);
    assert!(
        (mp.mass - exact.mass).abs() < 1e-3 * exact.mass,
        "hull mass {} vs {}",
        mp.mass,
        exact.mass
    );
    assert!(mp.local_com.length() < 1e-4);
    for k in 0..3 {
        let (a, b) = (mp.inertia.col(k)[k], exact.inertia.col(k)[k]);
        assert!((a - b).abs() < 1e-3 * b, "inertia axis {k}: {a} vs {b}");
    }
    // Random sphere cloud: every input point inside every face plane.
    let cloud: Vec<Vec3> = (0..500)
        .map(|_| rng.vec3(-1.0, 1.0).normalize_or(Vec3::X) * rng.range(0.5, 1.0))
        .collect();
    let hull = ConvexHull::from_points(&cloud).unwrap();
    for p in &cloud {
        for f in hull.faces() {
            assert!(
                f.normal.dot(*p) <= f.offset + 1e-4,
                "point outside hull face"
            );
        }
    }
}
