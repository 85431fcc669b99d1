//! Random stacks of 3–5 boxes of mixed sizes (0.6–1.2 m), each box offset in x and z on the
//! one below so that every load's centre of mass is at least `margin` inside its face (a
//! stack in equilibrium), run for 20 s in both engines at each preset, with friction 0.5 and
//! without. Prints, per stack, the largest sideways drift of any box; a stack counts as
//! toppled past 10 cm sideways or 5 cm down. The same stacks as
//! `runtime/physics/tests/stacking.rs`: its generator and seed, copied, since the physics
//! tests cannot use this crate without building rapier for them.
//!
//! `cargo run --release -p onyx-physics-bench --example random_stacks -- [count] [margin_m] [seed]`

use onyx_physics::glam::Vec3;
use onyx_physics::PhysicsPreset;
use onyx_physics_bench::engine::{BodySpec, EngineKind, ShapeSpec, StepSettings};

/// splitmix64, as in the physics tests.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        let u = (self.next_u64() >> 40) as f32 / (1u64 << 24) as f32;
        lo + (hi - lo) * u
    }
}

/// Boxes (centre, half extents), each resting on the one below, every load's centre of mass
/// at least `margin` inside the face it rests on.
fn random_stack(rng: &mut Rng, count: usize, margin: f32) -> Vec<(Vec3, Vec3)> {
    'retry: loop {
        let mut boxes: Vec<(Vec3, Vec3)> = Vec::new();
        let mut y = 0.0;
        for _ in 0..count {
            let half = Vec3::new(
                rng.range(0.35, 0.6),
                rng.range(0.3, 0.5),
                rng.range(0.35, 0.6),
            );
            let (x, z) = match boxes.last() {
                None => (0.0, 0.0),
                Some(below) => (
                    below.0.x + rng.range(-0.3, 0.3),
                    below.0.z + rng.range(-0.3, 0.3),
                ),
            };
            boxes.push((Vec3::new(x, y + half.y, z), half));
            y += 2.0 * half.y;
        }
        for i in 0..count - 1 {
            let (mut m, mut c) = (0.0, Vec3::ZERO);
            for &(p, h) in &boxes[i + 1..] {
                let v = h.x * h.y * h.z;
                m += v;
                c += p * v;
            }
            let c = c / m;
            let (lo, hi) = (boxes[i], boxes[i + 1]);
            for axis in [0, 2] {
                let min = (lo.0[axis] - lo.1[axis]).max(hi.0[axis] - hi.1[axis]);
                let max = (lo.0[axis] + lo.1[axis]).min(hi.0[axis] + hi.1[axis]);
                if c[axis] < min + margin || c[axis] > max - margin {
                    continue 'retry;
                }
            }
        }
        return boxes;
    }
}

/// Largest sideways drift and largest drop of any box after 20 s, m.
fn settle(
    engine: EngineKind,
    s: StepSettings,
    stack: &[(Vec3, Vec3)],
    friction: f32,
) -> (f32, f32) {
    let mut e = engine.create(s);
    e.add(&BodySpec::ground(Vec3::ZERO, 10.0).friction(friction));
    let ids: Vec<_> = stack
        .iter()
        .map(|&(p, h)| {
            (
                e.add(&BodySpec::dynamic(ShapeSpec::Cuboid(h), p).friction(friction)),
                p,
            )
        })
        .collect();
    for _ in 0..(20.0 * s.hz) as usize {
        e.step();
    }
    ids.iter()
        .fold((0.0f32, 0.0f32), |(side, drop), &(id, p0)| {
            let p = e.position(id);
            let d = Vec3::new(p.x - p0.x, 0.0, p.z - p0.z).length();
            (side.max(d), drop.max(p0.y - p.y))
        })
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let count: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(10);
    let margin: f32 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(0.1);
    let seed: u64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(15);
    let mut rng = Rng(seed);
    let stacks: Vec<_> = (0..count)
        .map(|k| random_stack(&mut rng, 3 + k % 3, margin))
        .collect();
    for preset in PhysicsPreset::ALL {
        let s = StepSettings::of_preset(preset);
        for friction in [0.5, 0.0] {
            let mut toppled = [0usize; 2];
            let mut line = format!("{preset:<8} friction {friction}:");
            for stack in &stacks {
                for (k, engine) in [EngineKind::Onyx, EngineKind::Rapier]
                    .into_iter()
                    .enumerate()
                {
                    let (side, drop) = settle(engine, s, stack, friction);
                    let fell = side > 0.1 || drop > 0.05 || !side.is_finite();
                    toppled[k] += usize::from(fell);
                    line.push_str(&format!(" {}{side:.1e}", ["o", "r"][k]));
                }
                line.push_str(" |");
            }
            println!("{line}");
            println!(
                "  toppled: onyx {} of {count}, rapier {} of {count}",
                toppled[0], toppled[1]
            );
        }
    }
}
