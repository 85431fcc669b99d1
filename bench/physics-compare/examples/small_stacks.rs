//! Columns of 2, 5 and 10 equal cubes from 1 mm to 10 m, placed touching on the ground with
//! friction 0.6, run for 10 s in both engines at each preset. Prints, per size and count,
//! the largest penetration of any contact over the last 5 s as a share of the cube's size,
//! or `FELL` where the top cube drifted more than a fifth of its size sideways or a contact
//! went half its size deep. Issue 15's size class: columns of small cubes topple at every
//! preset (see docs/physics-accuracy.md, *Where Onyx is behind*).
//!
//! `cargo run --release -p onyx-physics-bench --example small_stacks [-- SIZE COUNT]`

use onyx_physics::glam::Vec3;
use onyx_physics::PhysicsPreset;
use onyx_physics_bench::engine::{BodySpec, EngineKind, ShapeSpec, StepSettings};

/// Cube edges, m.
const SIZES: [f32; 7] = [0.001, 0.003, 0.01, 0.03, 0.1, 1.0, 10.0];

/// Cubes per column.
const COUNTS: [usize; 3] = [2, 5, 10];

/// Largest penetration over the last half of 10 s as a share of `size`, or `None` where the
/// column fell.
fn column(engine: EngineKind, s: StepSettings, size: f32, count: usize) -> Option<f32> {
    let mut e = engine.create(s);
    e.add(&BodySpec::ground(Vec3::ZERO, 100.0).friction(0.6));
    let half = Vec3::splat(0.5 * size);
    let ids: Vec<_> = (0..count)
        .map(|i| {
            let p = Vec3::new(0.0, size * (0.5 + i as f32), 0.0);
            e.add(&BodySpec::dynamic(ShapeSpec::Cuboid(half), p).friction(0.6))
        })
        .collect();
    let steps = (10.0 * s.hz) as usize;
    let mut deepest = 0.0f32;
    for k in 0..steps {
        e.step();
        if k >= steps / 2 {
            let ys: Vec<f32> = ids.iter().map(|&id| e.position(id).y).collect();
            let mut pen = 0.5 * size - ys[0];
            for i in 1..count {
                pen = pen.max(size - (ys[i] - ys[i - 1]));
            }
            deepest = deepest.max(pen);
        }
    }
    let top = e.position(ids[count - 1]);
    let drift = Vec3::new(top.x, 0.0, top.z).length();
    (drift.is_finite() && drift <= 0.2 * size && deepest <= 0.5 * size).then_some(deepest / size)
}

fn main() {
    // `small_stacks SIZE COUNT`: that column only, in Onyx at each preset.
    let args: Vec<f32> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    if let [size, count] = args[..] {
        for preset in PhysicsPreset::ALL {
            let s = StepSettings::of_preset(preset);
            let r = column(EngineKind::Onyx, s, size, count as usize);
            println!("{preset:<8} {size}×{count}: {r:?}");
        }
        return;
    }
    for preset in PhysicsPreset::ALL {
        let s = StepSettings::of_preset(preset);
        for engine in [EngineKind::Onyx, EngineKind::Rapier] {
            let mut line = format!("{preset:<8} {engine:?}:");
            for size in SIZES {
                for count in COUNTS {
                    let r = column(engine, s, size, count);
                    line.push_str(&match r {
                        Some(p) => format!(" {size}×{count} {:.1}%", 100.0 * p),
                        None => format!(" {size}×{count} FELL"),
                    });
                }
            }
            println!("{line}");
        }
    }
}
