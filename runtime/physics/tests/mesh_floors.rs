//! Bodies resting on a triangle-mesh floor (what a glTF level gives): anywhere on a wide
//! triangle, and across the edge two coplanar triangles share, as they rest on a plane.
//!
//! A 10 cm box placed on a triangle 2 km wide, 10 m from the floor's diagonal, found no
//! contact three steps in four (GJK's distance on the triangle's kilometre simplex read
//! 0.6 m) and fell into the floor between them; on the diagonal, each triangle's manifold
//! held the face's two shared corners again, and a 1 mm box drifted 7 % of its size in
//! 10 s at fast while a column of three 1 cm cubes drifted 36 % of a cube at balanced.
mod common;
use common::*;
use onyx_physics::glam::Vec3;
use onyx_physics::{
    BodyHandle, ColliderDesc, PhysicsPreset, PhysicsSettings, PhysicsWorld, RigidBodyDesc,
};

/// Half the width of the two-triangle floor, metres.
const FLOOR_HALF: f32 = 1000.0;

/// A world with a floor of two triangles (`y = 0`, 2 km square, split along `x = z`).
fn floor_world(preset: PhysicsPreset) -> PhysicsWorld {
    let mut w = PhysicsWorld::new(PhysicsSettings {
        sleep_enabled: false,
        ..preset.settings()
    });
    let e = FLOOR_HALF;
    let corners = vec![
        Vec3::new(-e, 0.0, -e),
        Vec3::new(e, 0.0, -e),
        Vec3::new(e, 0.0, e),
        Vec3::new(-e, 0.0, e),
    ];
    let floor = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(
        ColliderDesc::trimesh(corners, vec![[0, 2, 1], [0, 3, 2]]).expect("two triangles"),
        floor,
    );
    w
}

/// A cube of half size `half` as a hull (the shape a model's collider gets).
fn hull_cube(half: f32) -> ColliderDesc {
    ColliderDesc::convex_hull(&cube_corners(half)).expect("a cube is a hull")
}

/// Cubes of half size `half` stacked at `(x, z)` on the floor, run for 10 s. Returns, over the cubes, the largest
/// depth of a cube into what it rests on and the largest sideways move, as fractions of the
/// cube's size.
fn stack_on_floor(preset: PhysicsPreset, half: f32, count: usize, x: f32, z: f32) -> (f32, f32) {
    let mut w = floor_world(preset);
    let size = 2.0 * half;
    let cubes: Vec<(BodyHandle, Vec3)> = (0..count)
        .map(|i| {
            let p = Vec3::new(x, half + i as f32 * size, z);
            let b = w.insert_body(RigidBodyDesc::dynamic().translation(p));
            w.insert_collider(hull_cube(half), b);
            (b, p)
        })
        .collect();
    let steps = (10.0 / w.settings().dt) as usize;
    run(&mut w, steps);
    let (mut depth, mut sideways, mut below) = (0.0f32, 0.0f32, 0.0f32);
    for &(b, p0) in &cubes {
        let p = w.body(b).unwrap().translation();
        let sag = p0.y - p.y;
        depth = depth.max((sag - below).abs() / size);
        below = sag;
        sideways = sideways.max(Vec3::new(p.x - p0.x, 0.0, p.z - p0.z).length() / size);
    }
    (depth, sideways)
}

#[test]
fn cubes_rest_on_a_two_triangle_floor_anywhere_on_it() {
    let mut failures = Vec::new();
    for preset in [PhysicsPreset::Balanced, PhysicsPreset::Precise] {
        // On the shared edge, beside it, 10 m and 300 m from it.
        for (x, z) in [(0.0f32, 0.0f32), (-0.3, 0.3), (-7.0, 7.0), (300.0, -300.0)] {
            for (half, count) in [(0.005f32, 1), (0.005, 3), (0.05, 1), (0.05, 3), (0.5, 3)] {
                let (depth, sideways) = stack_on_floor(preset, half, count, x, z);
                println!(
                    "{preset} {count} × {} m cubes at ({x}, {z}): depth {depth:.4}, sideways \
                     {sideways:.2e} (of a cube)",
                    2.0 * half
                );
                if !(depth <= 0.05 && sideways < 0.01) {
                    failures.push(format!(
                        "{preset}: {count} cubes of {} m at ({x}, {z}) rest {depth} of a cube \
                         deep (expected ≤ 0.05) and moved {sideways} of one sideways \
                         (expected < 0.01)",
                        2.0 * half
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// At fast too, a lone cube on the shared edge stays where it was put (it rests deeper,
/// within the step's stiffness, but does not wander).
#[test]
fn a_cube_on_the_edge_two_triangles_share_stays_put_at_fast() {
    for half in [0.0005f32, 0.005, 0.05] {
        let (_, sideways) = stack_on_floor(PhysicsPreset::Fast, half, 1, 0.0, 0.0);
        println!(
            "fast {} m cube on the diagonal: sideways {sideways:.2e}",
            2.0 * half
        );
        assert!(
            sideways < 0.01,
            "fast: a {} m cube on the floor's shared edge moved {sideways} of its size",
            2.0 * half
        );
    }
}
