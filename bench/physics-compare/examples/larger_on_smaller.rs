//! A cube resting centred on a smaller one (edge ratios 2, 3 and 10: mass ratios 8, 27 and
//! 1000), from 1 mm to 1 m, with friction 0.5 and without, run for 10 s in both engines at
//! each preset. Physically both cubes stay where they were placed: the load's centre is over
//! the small cube's face and nothing pushes sideways. Prints, per case, the top cube's drift
//! aside as a share of its size after 10 s and the deepest either face sat over the last 5 s
//! as a share of the small cube (`drift/depth`; `FELL` where the top cube drifted past half
//! its size or a face sat half the small cube deep). The bounds: no drift, depth
//! within 5 %.
//!
//! `cargo run --release -p onyx-physics-bench --example larger_on_smaller [-- LOWER RATIO MU]`

use onyx_physics::glam::Vec3;
use onyx_physics::PhysicsPreset;
use onyx_physics_bench::engine::{BodySpec, EngineKind, ShapeSpec, StepSettings};

/// Edges of the lower cube, m.
const LOWER: [f32; 4] = [0.001, 0.01, 0.1, 1.0];

/// Edge of the upper cube over the lower one's.
const RATIOS: [f32; 3] = [2.0, 3.0, 10.0];

/// The upper cube's drift aside after 10 s over its size, and the deepest either face sat
/// over the last 5 s over the lower cube's size.
fn drift(engine: EngineKind, s: StepSettings, lower: f32, ratio: f32, mu: f32) -> (f32, f32) {
    let mut e = engine.create(s);
    e.add(&BodySpec::ground(Vec3::ZERO, 100.0).friction(mu));
    let upper = ratio * lower;
    let bottom = e.add(
        &BodySpec::dynamic(
            ShapeSpec::Cuboid(Vec3::splat(0.5 * lower)),
            Vec3::Y * 0.5 * lower,
        )
        .friction(mu),
    );
    let top = e.add(
        &BodySpec::dynamic(
            ShapeSpec::Cuboid(Vec3::splat(0.5 * upper)),
            Vec3::Y * (lower + 0.5 * upper),
        )
        .friction(mu),
    );
    let steps = (10.0 * s.hz) as usize;
    let mut deepest = 0.0f32;
    for k in 0..steps {
        e.step();
        if k >= steps / 2 {
            let (yl, yu) = (e.position(bottom).y, e.position(top).y);
            let ground = 0.5 * lower - yl;
            let face = (yl + 0.5 * lower) - (yu - 0.5 * upper);
            deepest = deepest.max(ground.max(face) / lower);
        }
    }
    let p = e.position(top);
    let d = Vec3::new(p.x, 0.0, p.z).length() / upper;
    (if d.is_finite() { d } else { f32::INFINITY }, deepest)
}

/// Whether the top cube drifted past half its size or a face sat half the small cube deep.
fn fell((d, depth): (f32, f32)) -> bool {
    d > 0.5 || depth.is_nan() || depth > 0.5
}

fn cell((d, depth): (f32, f32)) -> String {
    if fell((d, depth)) {
        "FELL".into()
    } else {
        format!("{:.1}%/{:.1}%", 100.0 * d, 100.0 * depth)
    }
}

fn main() {
    let args: Vec<f32> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    if let [lower, ratio, mu] = args[..] {
        for preset in PhysicsPreset::ALL {
            let s = StepSettings::of_preset(preset);
            let r = drift(EngineKind::Onyx, s, lower, ratio, mu);
            println!("{preset:<8} {lower} m, {ratio}× on it, μ {mu}: {}", cell(r));
        }
        return;
    }
    let (mut falls, mut cases) = ([[0u32; 2]; 3], 0);
    for mu in [0.5f32, 0.0] {
        for (pi, preset) in PhysicsPreset::ALL.into_iter().enumerate() {
            let s = StepSettings::of_preset(preset);
            for (ei, engine) in [EngineKind::Onyx, EngineKind::Rapier]
                .into_iter()
                .enumerate()
            {
                let mut line = format!("μ {mu} {preset:<8} {engine:<6?}:");
                for lower in LOWER {
                    for ratio in RATIOS {
                        let d = drift(engine, s, lower, ratio, mu);
                        falls[pi][ei] += u32::from(fell(d));
                        line.push_str(&format!(" {lower}×{ratio} {}", cell(d)));
                    }
                }
                println!("{line}");
            }
        }
        cases += LOWER.len() * RATIOS.len();
    }
    for (pi, preset) in PhysicsPreset::ALL.into_iter().enumerate() {
        println!(
            "{preset:<8} fell: onyx {} of {cases}, rapier {} of {cases}",
            falls[pi][0], falls[pi][1]
        );
    }
}
