//! Tall stacks held for a long run: `COUNT` cubes of `SIZE` m (every other one set aside by
//! `OFFSET` of its size; friction 0.6) placed touching on a ground, run for `SECONDS` in both
//! engines at each preset. Prints, per preset and engine, the cost of a step and how far the
//! top cube has moved sideways since the stack settled (at 2 s), as a share of its size, at
//! eight even times to the end: a stack whose faces are soft in tilt leans over slowly, in a
//! tilt that grows by a factor each second, and a run as short as the accuracy sweep's
//! `stack` scene (1000 steps) can end before it shows. Issue 15's tall stacks.
//!
//! `cargo run --release -p onyx-physics-bench --example tall_stack [-- SIZE COUNT SECONDS [OFFSET]]`
//! (default: 20 cubes of 10 cm, 30 cm and 1 m for 60 s).

use onyx_physics::glam::Vec3;
use onyx_physics::PhysicsPreset;
use onyx_physics_bench::engine::{BodySpec, EngineKind, ShapeSpec, StepSettings};

/// Friction of the cubes and the ground.
const FRICTION: f32 = 0.6;

/// Seconds the stack settles before its top's place is taken.
const SETTLE: f32 = 2.0;

/// Times the top's drift is printed, evenly to the end.
const SAMPLES: usize = 8;

/// Runs one stack; returns the ms per step after settling and the top's sideways drift (share
/// of `size`) at each sample.
fn run(
    engine: EngineKind,
    s: StepSettings,
    size: f32,
    count: usize,
    seconds: f32,
    offset: f32,
) -> (f64, Vec<f32>) {
    let mut e = engine.create(s);
    e.add(&BodySpec::ground(Vec3::ZERO, 100.0).friction(FRICTION));
    let half = Vec3::splat(0.5 * size);
    let mut top = None;
    for i in 0..count {
        let p = Vec3::new(offset * size * (i % 2) as f32, size * (0.5 + i as f32), 0.0);
        top = Some(e.add(&BodySpec::dynamic(ShapeSpec::Cuboid(half), p).friction(FRICTION)));
    }
    let Some(top) = top else {
        return (0.0, Vec::new());
    };
    for _ in 0..(SETTLE * s.hz) as usize {
        e.step();
    }
    let settled = e.position(top);
    let per_sample = (((seconds - SETTLE) / SAMPLES as f32) * s.hz).max(1.0) as usize;
    let started = std::time::Instant::now();
    let drift = (0..SAMPLES)
        .map(|_| {
            for _ in 0..per_sample {
                e.step();
            }
            let d = e.position(top) - settled;
            Vec3::new(d.x, 0.0, d.z).length() / size
        })
        .collect();
    let ms = started.elapsed().as_secs_f64() * 1e3 / (per_sample * SAMPLES) as f64;
    (ms, drift)
}

fn main() {
    let args: Vec<f32> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let stacks: Vec<(f32, usize, f32, f32)> = match args[..] {
        [size, count, seconds] => vec![(size, count as usize, seconds, 0.0)],
        [size, count, seconds, offset, ..] => vec![(size, count as usize, seconds, offset)],
        _ => [0.1, 0.3, 1.0].map(|size| (size, 20, 60.0, 0.0)).to_vec(),
    };
    for (size, count, seconds, offset) in stacks {
        println!("{count} cubes of {size} m, every other one {offset} aside, {seconds} s:");
        for preset in PhysicsPreset::ALL {
            let s = StepSettings::of_preset(preset);
            for engine in [EngineKind::Onyx, EngineKind::Rapier] {
                let (ms, drift) = run(engine, s, size, count, seconds, offset);
                let drift: Vec<String> = drift.iter().map(|d| format!("{d:.3}")).collect();
                println!(
                    "  {preset:<8} {:<7} {ms:.3} ms/step, top aside (of a cube): {}",
                    engine.name(),
                    drift.join(" ")
                );
            }
        }
    }
}
