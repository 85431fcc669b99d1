//! One scene in one engine at 60 Hz × 4, full size, for a profiler: prints the scene's figure,
//! the mean ms/step (every step counted, the first included), the spread of single steps and,
//! for Onyx, the time per stage.
//!
//! `cargo run --release -p onyx-physics-bench --example profile_scene -- pyramid [onyx|rapier] [repeats]`
//! then e.g. `perf record -g target/release/examples/profile_scene pyramid onyx`.

use std::time::Instant;

use onyx_physics_bench::engine::{EngineKind, StepSettings};
use onyx_physics_bench::scenes::{all, Size};

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let name = args.get(1).map_or("pyramid", String::as_str);
    let engine = match args.get(2).map(String::as_str) {
        Some("rapier") => EngineKind::Rapier,
        _ => EngineKind::Onyx,
    };
    let repeats: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(1);
    let scene = all()
        .into_iter()
        .find(|s| s.name() == name)
        .ok_or_else(|| anyhow::anyhow!("unknown scene {name:?}"))?;
    let s = StepSettings {
        hz: 60.0,
        iterations: 4,
    };
    let (mut seconds, mut steps_run) = (0.0, 0usize);
    let mut step_ms = Vec::new();
    for _ in 0..repeats {
        let mut e = engine.create(s);
        let mut trial = scene.build(e.as_mut(), s, Size::Full);
        let steps = scene.steps(s, Size::Full);
        let t = Instant::now();
        for _ in 0..steps {
            let step = Instant::now();
            e.step();
            step_ms.push(step.elapsed().as_secs_f64() * 1e3);
            trial.observe(e.as_ref());
        }
        seconds += t.elapsed().as_secs_f64();
        steps_run += steps;
        println!("figure {}", trial.figure(e.as_ref()));
        for (stage, sum) in e.stage_seconds() {
            println!(
                "  {stage:<12} {:.4} ms/step",
                sum * 1e3 / steps.max(1) as f64
            );
        }
    }
    println!(
        "{name} {}: {:.4} ms/step (mean over {steps_run} steps)",
        engine.name(),
        seconds * 1e3 / steps_run.max(1) as f64
    );
    // The sweep reports the median step (first excluded); the quartiles show where time goes.
    step_ms.sort_by(f64::total_cmp);
    let at = |q: f64| step_ms[((step_ms.len() - 1) as f64 * q).round() as usize];
    if !step_ms.is_empty() {
        println!(
            "  step ms: min {:.4}, quartiles {:.4} / {:.4} / {:.4}, max {:.4}",
            at(0.0),
            at(0.25),
            at(0.5),
            at(0.75),
            at(1.0)
        );
    }
    Ok(())
}
