//! Sliding friction: a 1 m box launched at 5 m/s on a ground, μ = 0.5 on both. Error:
//! |d − v²/(2 μ g)| (stopping distance, m) after 2 s (it stops at ≈1.02 s).

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodySpec, Engine, ShapeSpec, StepSettings};

const V0: f32 = 5.0;
const MU: f32 = 0.5;
const G: f32 = 9.81;

/// See the module docs.
pub struct Sliding;

struct Run {
    x0: f32,
}

impl Scene for Sliding {
    fn name(&self) -> &'static str {
        "sliding"
    }
    fn metric(&self) -> &'static str {
        "|stopping distance - v^2/(2 mu g)|, m"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(2.0, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        e.add(&BodySpec::ground(Vec3::ZERO, 20.0).friction(MU));
        let x0 = -5.0;
        e.add(
            &BodySpec::dynamic(ShapeSpec::Cuboid(Vec3::splat(0.5)), Vec3::new(x0, 0.5, 0.0))
                .friction(MU)
                .velocity(Vec3::new(V0, 0.0, 0.0)),
        );
        Box::new(Run { x0 })
    }
}

impl Trial for Run {
    fn figure(&self, e: &dyn Engine) -> f64 {
        let d = f64::from(e.position(1).x - self.x0);
        let expected = f64::from(V0 * V0 / (2.0 * MU * G));
        (d - expected).abs()
    }
}
