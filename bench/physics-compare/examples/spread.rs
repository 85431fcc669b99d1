//! How much one scene's figure moves when its start moves by a micrometre: the scene built
//! several times in each engine with every dynamic body shifted by a different ±1 µm
//! (deterministic seeds; seed 0 is the unshifted scene), at the balanced (60 Hz × 4) and
//! precise (120 Hz × 4) settings. A chaotic scene (a poured pile, a collapsing pyramid) has
//! a figure that is one sample of a spread; the sweep reports seed 0.
//!
//! `cargo run --release -p onyx-physics-bench --example spread -- poured_spheres [seeds] [all]`
//! (`all`: fast too).

use onyx_physics::glam::Quat;
use onyx_physics::glam::Vec3;
use onyx_physics::PhysicsPreset;
use onyx_physics_bench::engine::{BodyId, BodySpec, Engine, EngineKind, StepSettings};
use onyx_physics_bench::joint_spec::JointSpec;
use onyx_physics_bench::scenes::{all, Size};

/// An engine whose dynamic bodies start shifted by up to 1 µm per axis.
struct Shifted {
    inner: Box<dyn Engine>,
    state: u64,
}

impl Shifted {
    /// Uniform in [-1, 1) (a 64-bit LCG: deterministic per seed).
    fn next(&mut self) -> f32 {
        self.state = self
            .state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.state >> 40) as f32 / (1u64 << 23) as f32 - 1.0
    }
}

impl Engine for Shifted {
    fn kind(&self) -> EngineKind {
        self.inner.kind()
    }
    fn add(&mut self, spec: &BodySpec) -> BodyId {
        let mut spec = *spec;
        if !spec.fixed && self.state != 0 {
            spec.position += Vec3::new(self.next(), self.next(), self.next()) * 1e-6;
        }
        self.inner.add(&spec)
    }
    fn add_joint(&mut self, spec: &JointSpec) {
        self.inner.add_joint(spec);
    }
    fn joint_count(&self) -> usize {
        self.inner.joint_count()
    }
    fn step(&mut self) {
        self.inner.step();
    }
    fn position(&self, id: BodyId) -> Vec3 {
        self.inner.position(id)
    }
    fn rotation(&self, id: BodyId) -> Quat {
        self.inner.rotation(id)
    }
    fn velocity(&self, id: BodyId) -> Vec3 {
        self.inner.velocity(id)
    }
    fn angular_velocity(&self, id: BodyId) -> Vec3 {
        self.inner.angular_velocity(id)
    }
    fn mass(&self, id: BodyId) -> f32 {
        self.inner.mass(id)
    }
    fn kinetic_energy(&self, id: BodyId) -> f64 {
        self.inner.kinetic_energy(id)
    }
    fn angular_momentum(&self, id: BodyId) -> f64 {
        self.inner.angular_momentum(id)
    }
    fn set_restitution_threshold(&mut self, speed: f32) -> bool {
        self.inner.set_restitution_threshold(speed)
    }
    fn len(&self) -> usize {
        self.inner.len()
    }
}

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let name = args.get(1).map_or("poured_spheres", String::as_str);
    let seeds: u64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(5);
    let scene = all()
        .into_iter()
        .find(|s| s.name() == name)
        .ok_or_else(|| anyhow::anyhow!("unknown scene {name:?}"))?;
    println!("{name}: {}", scene.metric());
    // `all` as the third argument adds fast (30 Hz × 2), whose collapses are the widest.
    let presets: &[PhysicsPreset] = if args.get(3).is_some_and(|a| a == "all") {
        &PhysicsPreset::ALL
    } else {
        &[PhysicsPreset::Balanced, PhysicsPreset::Precise]
    };
    for &preset in presets {
        let (label, s) = (preset.to_string(), StepSettings::of_preset(preset));
        for engine in EngineKind::ALL {
            let figures: Vec<f64> = (0..seeds)
                .map(|seed| {
                    let mut e = Shifted {
                        inner: engine.create(s),
                        state: seed,
                    };
                    let mut trial = scene.build(&mut e, s, Size::Full);
                    for _ in 0..scene.steps(s, Size::Full) {
                        e.step();
                        trial.observe(&e);
                    }
                    trial.figure(&e)
                })
                .collect();
            let mean = figures.iter().sum::<f64>() / figures.len().max(1) as f64;
            let (lo, hi) = figures
                .iter()
                .fold((f64::MAX, f64::MIN), |(l, h), &f| (l.min(f), h.max(f)));
            let list: Vec<String> = figures.iter().map(|f| format!("{f:.4}")).collect();
            println!(
                "{label:8} {:6}: mean {mean:.4}, range {lo:.4}..{hi:.4} ({})",
                engine.name(),
                list.join(", ")
            );
        }
    }
    Ok(())
}
