//! A heavy box resting off centre on a light one (40 cm cubes on a ground box), in both
//! engines at each preset, for mass ratios from 1:1 to 1000:1 and offsets from 0 to 10 cm
//! (in x, and half that in z). Both are in equilibrium: the load's centre is over the light
//! box's face. Prints, per ratio and offset, how deep the heavy box sits in the light one
//! after 3 s (mm; 400 mm: it went through) and the largest tilt of the heavy box (rad).
//!
//! `cargo run --release -p onyx-physics-bench --example offset_heavy`

use onyx_physics::glam::{Quat, Vec3};
use onyx_physics::PhysicsPreset;
use onyx_physics_bench::engine::{BodySpec, EngineKind, ShapeSpec, StepSettings};

/// Half the cubes' size, m.
const H: f32 = 0.2;

/// Depth of the heavy box in the light one after 3 s (m) and its largest tilt (rad).
fn run(engine: EngineKind, s: StepSettings, ratio: f32, offset: f32) -> (f32, f32) {
    let mut e = engine.create(s);
    e.add(&BodySpec::ground(Vec3::ZERO, 10.0));
    let cube = ShapeSpec::Cuboid(Vec3::splat(H));
    let light = e.add(&BodySpec::dynamic(cube, Vec3::Y * H));
    let heavy = e.add(
        &BodySpec::dynamic(cube, Vec3::new(offset, 3.0 * H, -0.5 * offset)).density(1000.0 * ratio),
    );
    let mut tilt = 0.0f32;
    for _ in 0..(3.0 * s.hz) as usize {
        e.step();
        tilt = tilt.max(e.rotation(heavy).angle_between(Quat::IDENTITY));
    }
    let depth = (e.position(light).y + H) - (e.position(heavy).y - H);
    (depth, tilt)
}

fn main() {
    let offsets = [0.0f32, 0.01, 0.03, 0.06, 0.1];
    println!("offsets {offsets:?} m; each cell: onyx depth/tilt, rapier depth/tilt");
    for preset in PhysicsPreset::ALL {
        let s = StepSettings::of_preset(preset);
        for ratio in [1.0f32, 3.0, 10.0, 30.0, 100.0, 1000.0] {
            let mut line = format!("{preset:<8} {ratio:>5}:1");
            for &offset in &offsets {
                for (engine, tag) in [(EngineKind::Onyx, 'o'), (EngineKind::Rapier, 'r')] {
                    let (depth, tilt) = run(engine, s, ratio, offset);
                    line.push_str(&format!(" {tag} {:.1}mm/{tilt:.2}", depth * 1e3));
                }
                line.push_str(" |");
            }
            println!("{line}");
        }
    }
}
