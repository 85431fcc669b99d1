//! World-pose propagation of the scene graph, for 100,000 entities in trees of depth 8
//! (branching 3: 30 full trees of 3,280 and one partial), next to a flat hecs query over the
//! same entities in the same run:
//!
//! - all moving: every entity's local transform written (and reported) before each
//!   propagation — the write is not timed, the propagation is;
//! - nothing moving: a propagation after a frame in which nothing changed;
//! - one subtree moving: a root of 3,280 entities moved;
//! - the peer: one flat pass over the same entities' `Transform`s computing each local
//!   matrix (what an engine without a hierarchy pays to get every pose).
//!
//! Goals on the project's 2-core machine: all moving < 2 ms, nothing moving < 0.2 ms.
//! `cargo bench -p onyx-runtime --bench hierarchy`

use std::hint::black_box;
use std::time::{Duration, Instant};

use onyx_plugin_api::glam::{Affine3A, Quat, Vec3};
use onyx_plugin_api::{Entity, Parent, Transform};
use onyx_runtime::hierarchy::TransformHierarchy;

const ENTITIES: usize = 100_000;
const DEPTH: usize = 8;
const BRANCHING: usize = 3;

fn api(e: hecs::Entity) -> Entity {
    Entity::from_bits(e.to_bits().get())
}

/// The trees, parents before children; the roots are the first entity of each tree.
fn build(world: &mut hecs::World) -> (Vec<hecs::Entity>, Vec<hecs::Entity>) {
    let mut all = Vec::with_capacity(ENTITIES);
    let mut roots = Vec::new();
    while all.len() < ENTITIES {
        let root = world.spawn((Transform::from_xyz(all.len() as f32, 0.0, 0.0),));
        roots.push(root);
        all.push(root);
        let mut level = vec![root];
        for depth in 1..DEPTH {
            let mut next = Vec::new();
            for &parent in &level {
                for k in 0..BRANCHING {
                    if all.len() == ENTITIES {
                        return (all, roots);
                    }
                    let local = Transform::from_xyz(1.0, 0.1 * k as f32, 0.0)
                        .with_rotation(Quat::from_rotation_y(0.1 * depth as f32))
                        .with_scale(Vec3::splat(0.95));
                    let child = world.spawn((local, Parent(api(parent))));
                    next.push(child);
                    all.push(child);
                }
            }
            level = next;
        }
    }
    (all, roots)
}

/// Median of `rounds` samples of `f`, which returns the time it measured.
fn median(rounds: usize, mut f: impl FnMut() -> Duration) -> Duration {
    let mut samples: Vec<Duration> = (0..rounds).map(|_| f()).collect();
    samples.sort();
    samples[rounds / 2]
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

fn main() {
    // `cargo bench` passes `--bench`; any other argument (a filter) is ignored.
    let mut world = hecs::World::new();
    let (all, roots) = build(&mut world);
    let mut hierarchy = TransformHierarchy::new();
    hierarchy.invalidate();
    let start = Instant::now();
    hierarchy.propagate(&world);
    let first = start.elapsed();
    assert_eq!(hierarchy.len(), ENTITIES, "every entity is in a tree");

    let mut angle = 0.0f32;
    let all_moving = median(21, || {
        angle += 1e-3;
        for (t,) in world.query_mut::<(&mut Transform,)>() {
            t.rotation = Quat::from_rotation_z(angle);
        }
        for &e in &all {
            hierarchy.moved(e);
        }
        let start = Instant::now();
        hierarchy.propagate(&world);
        start.elapsed()
    });
    let nothing_moving = median(101, || {
        let start = Instant::now();
        hierarchy.propagate(&world);
        start.elapsed()
    });
    let one_tree = median(51, || {
        angle += 1e-3;
        if let Ok(mut t) = world.get::<&mut Transform>(roots[0]) {
            t.rotation = Quat::from_rotation_x(angle);
        }
        hierarchy.moved(roots[0]);
        let start = Instant::now();
        hierarchy.propagate(&world);
        start.elapsed()
    });
    let flat = median(21, || {
        let start = Instant::now();
        let mut sum = Affine3A::ZERO;
        for t in world.query::<&Transform>().iter() {
            sum.translation += t.affine().translation;
        }
        black_box(sum);
        start.elapsed()
    });
    // The propagated poses are the composed matrices (a spot check of the deepest entity).
    let deepest = *all.last().expect("entities were built");
    let mut expected = Affine3A::IDENTITY;
    let mut chain = vec![deepest];
    while let Ok(parent) = world.get::<&Parent>(*chain.last().expect("non-empty")) {
        chain.push(hecs::Entity::from_bits(parent.0.to_bits()).expect("a live parent"));
    }
    for e in chain.iter().rev() {
        expected *= world
            .get::<&Transform>(*e)
            .expect("has a transform")
            .affine();
    }
    let got = hierarchy.world_of(deepest, &Transform::IDENTITY);
    assert!(got.abs_diff_eq(expected, 1e-3), "{got:?} vs {expected:?}");

    println!(
        "\n== scene-graph propagation, {ENTITIES} entities in trees of depth {DEPTH} (median) =="
    );
    println!(
        "first propagation (index built from Parent components): {:8.3} ms",
        ms(first)
    );
    println!(
        "all moving:          {:8.3} ms   [goal < 2 ms]   {:.1}x the flat query",
        ms(all_moving),
        ms(all_moving) / ms(flat)
    );
    println!(
        "one tree moving:     {:8.3} ms   ({} entities)",
        ms(one_tree),
        hierarchy.subtree(roots[0]).len()
    );
    println!(
        "nothing moving:      {:8.1} µs   [goal < 0.2 ms]   {:.5}x the flat query",
        nothing_moving.as_secs_f64() * 1e6,
        ms(nothing_moving) / ms(flat)
    );
    println!(
        "flat hecs query (peer): {:5.3} ms   (one local matrix per entity)",
        ms(flat)
    );
}
