//! Columns of three, five and ten equal cubes, every other one set aside by 10–30 % of its size,
//! friction 0.5, placed touching on the ground, run for 10 s in both engines at each preset.
//! Prints, per preset and engine, how many of the 63 columns (5 mm–1 m) moved a cube more
//! than 1 % of its size sideways after they settled (between 2 s and 10 s: the tilt soft
//! contacts take under an off-centre load in the first steps is not counted), and the worst.
//! Issue 15's class of small offset stacks with friction that wobble (see
//! docs/physics-accuracy.md, *Where Onyx is behind*).
//!
//! `cargo run --release -p onyx-physics-bench --example offset_stacks [-- SIZE COUNT OFFSET]`

use onyx_physics::glam::Vec3;
use onyx_physics::PhysicsPreset;
use onyx_physics_bench::engine::{BodySpec, EngineKind, ShapeSpec, StepSettings};

/// Cube edges, m.
const SIZES: [f32; 7] = [0.005, 0.01, 0.02, 0.05, 0.1, 0.3, 1.0];

/// Cubes per column.
const COUNTS: [usize; 3] = [3, 5, 10];

/// How far every other cube is set aside, as a share of its size.
const OFFSETS: [f32; 3] = [0.1, 0.2, 0.3];

/// Friction of the cubes and the ground.
const FRICTION: f32 = 0.5;

/// A cube that moved more than this share of its size sideways has drifted.
const DRIFT: f32 = 0.01;

/// The largest sideways move of any cube between 2 s and 10 s (after the column settled),
/// as a share of `size`.
fn column(engine: EngineKind, s: StepSettings, size: f32, count: usize, offset: f32) -> f32 {
    let mut e = engine.create(s);
    e.add(&BodySpec::ground(Vec3::ZERO, 100.0).friction(FRICTION));
    let half = Vec3::splat(0.5 * size);
    let placed: Vec<_> = (0..count)
        .map(|i| {
            let x = offset * size * (i % 2) as f32;
            let p = Vec3::new(x, size * (0.5 + i as f32), 0.0);
            e.add(&BodySpec::dynamic(ShapeSpec::Cuboid(half), p).friction(FRICTION))
        })
        .collect();
    for _ in 0..(2.0 * s.hz) as usize {
        e.step();
    }
    let settled: Vec<_> = placed.iter().map(|&id| (id, e.position(id))).collect();
    for _ in 0..(8.0 * s.hz) as usize {
        e.step();
    }
    let mut worst = 0.0f32;
    for &(id, p) in &settled {
        let d = e.position(id) - p;
        let sideways = Vec3::new(d.x, 0.0, d.z).length() / size;
        worst = if sideways.is_finite() {
            worst.max(sideways)
        } else {
            f32::INFINITY
        };
    }
    worst
}

fn main() {
    // `offset_stacks SIZE COUNT OFFSET`: that column only, in both engines at each preset.
    let args: Vec<f32> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    if let [size, count, offset] = args[..] {
        for preset in PhysicsPreset::ALL {
            let s = StepSettings::of_preset(preset);
            for engine in [EngineKind::Onyx, EngineKind::Rapier] {
                let r = column(engine, s, size, count as usize, offset);
                println!(
                    "{preset:<8} {engine:?} {size}×{count} +{offset}: {:.2}%",
                    100.0 * r
                );
            }
        }
        return;
    }
    for preset in PhysicsPreset::ALL {
        let s = StepSettings::of_preset(preset);
        for engine in [EngineKind::Onyx, EngineKind::Rapier] {
            let mut drifted = Vec::new();
            let mut total = 0;
            for size in SIZES {
                for count in COUNTS {
                    for offset in OFFSETS {
                        total += 1;
                        let r = column(engine, s, size, count, offset);
                        if r > DRIFT {
                            drifted.push((r, format!("{size}×{count}+{offset}")));
                        }
                    }
                }
            }
            drifted.sort_by(|a, b| b.0.total_cmp(&a.0));
            let worst: Vec<String> = drifted
                .iter()
                .take(4)
                .map(|(r, name)| format!("{name} {:.1}%", 100.0 * r))
                .collect();
            println!(
                "{preset:<8} {:<7} {:>2} of {total} drifted > {:.0}%; worst: {}",
                engine.name(),
                drifted.len(),
                100.0 * DRIFT,
                worst.join(", ")
            );
        }
    }
}
