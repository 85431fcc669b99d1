use onyx_physics::glam::Vec3;
use onyx_physics::PhysicsPreset;
use onyx_physics_bench::engine::{BodySpec, EngineKind, ShapeSpec, StepSettings};
fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let size: f32 = a[0].parse().unwrap();
    let count: usize = a[1].parse().unwrap();
    let offset: f32 = a[2].parse().unwrap();
    let preset = match a[3].as_str() {
        "fast" => PhysicsPreset::Fast,
        "precise" => PhysicsPreset::Precise,
        _ => PhysicsPreset::Balanced,
    };
    let mu: f32 = a[4].parse().unwrap();
    let engine = if a.get(5).map(|s| s.as_str()) == Some("rapier") {
        EngineKind::Rapier
    } else {
        EngineKind::Onyx
    };
    let s = StepSettings::of_preset(preset);
    let mut e = engine.create(s);
    e.add(&BodySpec::ground(Vec3::ZERO, 100.0).friction(mu));
    let half = Vec3::splat(0.5 * size);
    let placed: Vec<_> = (0..count)
        .map(|i| {
            let x = offset * size * (i % 2) as f32;
            let p = Vec3::new(x, size * (0.5 + i as f32), 0.0);
            (
                e.add(&BodySpec::dynamic(ShapeSpec::Cuboid(half), p).friction(mu)),
                p,
            )
        })
        .collect();
    let steps = (10.0 * s.hz) as usize;
    for k in 0..steps {
        e.step();
        if k % (steps / 40) == 0 {
            let mut line = format!("{:5.2}s", k as f32 / s.hz);
            for &(id, p) in placed.iter().step_by(2) {
                let d = (e.position(id) - p) / size * 100.0;
                let q = e.rotation(id);
                let (ax, ang) = q.to_axis_angle();
                let r = ax * ang * 1e3;
                line.push_str(&format!(
                    " |{:5.1},{:5.1},{:5.1}% {:5.1},{:5.1},{:5.1}",
                    d.x, d.y, d.z, r.x, r.y, r.z
                ));
            }
            println!("{line}");
        }
    }
}
