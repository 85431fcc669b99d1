//! Tiny and huge: ten 1 cm spheres (r = 5 mm) resting on a 10 m ground, and a 1 m box resting
//! on a 1e4 m ground (half extent 5,000 m), all started exactly touching. Error: the largest
//! |resting height − expected| after 2 s, m.

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const R: f32 = 0.005;
const H: f32 = 0.5;
/// Top of the small ground (kept clear of the huge one, whose top is at y = 0).
const SMALL_TOP: f32 = 20.0;

/// See the module docs.
pub struct TinyHuge;

struct Run {
    /// (id, expected centre height).
    bodies: Vec<(BodyId, f32)>,
}

impl Scene for TinyHuge {
    fn name(&self) -> &'static str {
        "tiny_huge"
    }
    fn metric(&self) -> &'static str {
        "max |resting height - expected| (1 cm spheres, box on 1e4 m ground), m"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(2.0, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        e.add(&BodySpec::ground(Vec3::new(0.0, SMALL_TOP, 0.0), 5.0));
        e.add(&BodySpec::ground(Vec3::ZERO, 5_000.0));
        let mut bodies = Vec::new();
        for i in 0..10 {
            let y = SMALL_TOP + R;
            let p = Vec3::new(-2.0 + 0.4 * i as f32, y, 0.0);
            bodies.push((e.add(&BodySpec::dynamic(ShapeSpec::Sphere(R), p)), y));
        }
        let p = Vec3::new(100.0, H, 100.0);
        bodies.push((
            e.add(&BodySpec::dynamic(ShapeSpec::Cuboid(Vec3::splat(H)), p)),
            H,
        ));
        Box::new(Run { bodies })
    }
}

impl Trial for Run {
    fn figure(&self, e: &dyn Engine) -> f64 {
        let mut worst = 0.0f64;
        for &(id, y) in &self.bodies {
            let p = e.position(id);
            if !p.is_finite() {
                return f64::NAN;
            }
            worst = worst.max(f64::from((p.y - y).abs()));
        }
        worst
    }
}
