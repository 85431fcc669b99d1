//! Speculative contacts of bodies that go by others: made where the two come closest over
//! the step, they hold nothing the straight paths would not (see
//! `narrowphase/closest_approach.rs`).
mod common;
use onyx_physics::glam::Vec3;
use onyx_physics::{ColliderDesc, PhysicsPreset, PhysicsSettings, PhysicsWorld, RigidBodyDesc};

/// A frictionless ball, box or capsule gliding 2 mm or 1 cm over a 2 m block's top face, or
/// past its side, from 2 m before its edge to beyond the far one, with CCD on or off, keeps
/// its velocity; the block a box, a hull or a triangle mesh. The contact made at the step's start along the closest points, from the
/// edge to a body still before it, pointed back along its path, and the body was braked and
/// thrown up: a ball at 2–50 m/s lost nearly all its speed at every preset. Where a step's
/// travel is more than `speculative_distance` (below it, the start's contact holds at most
/// that distance's worth of the path, as in Box2D v3, see docs/physics-accuracy.md).
#[test]
fn a_body_gliding_past_an_edge_keeps_its_velocity() {
    let mut failures = Vec::new();
    let mut cases = 0;
    for preset in PhysicsPreset::ALL {
        let settings = PhysicsSettings {
            gravity: Vec3::ZERO,
            sleep_enabled: false,
            ..preset.settings()
        };
        for ccd in [false, true] {
            for (name, desc, half) in [
                ("ball", ColliderDesc::sphere(0.05), 0.05f32),
                ("box", ColliderDesc::cuboid(0.05, 0.05, 0.05), 0.05),
                // Along x, 5 cm thick.
                (
                    "capsule",
                    ColliderDesc::capsule(0.05, 0.025).rotation(
                        onyx_physics::glam::Quat::from_rotation_z(std::f32::consts::FRAC_PI_2),
                    ),
                    0.025,
                ),
            ] {
                for speed in [2.0f32, 5.0, 20.0, 50.0, 150.0] {
                    if speed * settings.dt <= settings.speculative_distance {
                        continue;
                    }
                    for (gap, side, kind) in cases_of([0.002f32, 0.01], [Vec3::Y, Vec3::Z]) {
                        {
                            cases += 1;
                            let mut w = PhysicsWorld::new(settings);
                            let block = w.insert_body(RigidBodyDesc::fixed());
                            w.insert_collider(block_collider(kind), block);
                            let b = w.insert_body(
                                RigidBodyDesc::dynamic()
                                    .translation(
                                        Vec3::new(-3.0, 0.0, 0.0) + side * (1.0 + half + gap),
                                    )
                                    .linvel(Vec3::X * speed)
                                    .ccd_enabled(ccd),
                            );
                            w.insert_collider(desc.clone().friction(0.0), b);
                            let steps = ((6.0 / speed) / settings.dt) as usize;
                            let mut off = 0.0f32;
                            for _ in 0..steps {
                                w.step();
                                let body = w.body(b).unwrap();
                                off = off.max((body.linvel() - Vec3::X * speed).length());
                            }
                            if off > 1e-3 * speed {
                                failures.push(format!(
                                    "{preset}, CCD {ccd}: {name} at {speed} m/s, {gap} m over the \
                                     {side:?} face of a {kind}: velocity off by {off} m/s"
                                ));
                            }
                        }
                    }
                }
            }
        }
    }
    println!("{} of {cases} disturbed", failures.len());
    assert!(
        failures.is_empty(),
        "bodies gliding past an edge were disturbed (expected not): {failures:#?}"
    );
}

/// Every gap, side and block kind.
fn cases_of(gaps: [f32; 2], sides: [Vec3; 2]) -> impl Iterator<Item = (f32, Vec3, &'static str)> {
    gaps.into_iter().flat_map(move |gap| {
        sides.into_iter().flat_map(move |side| {
            ["box", "hull", "mesh"]
                .into_iter()
                .map(move |kind| (gap, side, kind))
        })
    })
}

/// A 2 m block at the origin as a box, a hull or a closed triangle mesh.
fn block_collider(kind: &str) -> ColliderDesc {
    let corners: Vec<Vec3> = (0..8)
        .map(|i| {
            Vec3::new(
                if i & 1 == 0 { -1.0 } else { 1.0 },
                if i & 2 == 0 { -1.0 } else { 1.0 },
                if i & 4 == 0 { -1.0 } else { 1.0 },
            )
        })
        .collect();
    match kind {
        "hull" => ColliderDesc::convex_hull(&corners).expect("a cube is a hull"),
        "mesh" => ColliderDesc::trimesh(
            corners,
            vec![
                [0, 2, 3],
                [0, 3, 1],
                [4, 5, 7],
                [4, 7, 6],
                [0, 1, 5],
                [0, 5, 4],
                [2, 6, 7],
                [2, 7, 3],
                [0, 4, 6],
                [0, 6, 2],
                [1, 3, 7],
                [1, 7, 5],
            ],
        )
        .expect("a closed cube mesh"),
        _ => ColliderDesc::cuboid(1.0, 1.0, 1.0),
    }
}
