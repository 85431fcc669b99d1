//! Free fall: a sphere dropped from rest, no contacts. Error: |y − (y0 − ½ g t²)| after 2 s
//! (every swept rate divides 2 s into whole steps).

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodySpec, Engine, ShapeSpec, StepSettings};

const G: f64 = 9.81;
const Y0: f32 = 100.0;
const SECONDS: f32 = 2.0;

/// See the module docs.
pub struct FreeFall;

struct Run;

impl Scene for FreeFall {
    fn name(&self) -> &'static str {
        "free_fall"
    }
    fn metric(&self) -> &'static str {
        "|y - y_analytic| after 2 s, m"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(SECONDS, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        e.add(&BodySpec::dynamic(
            ShapeSpec::Sphere(0.5),
            Vec3::new(0.0, Y0, 0.0),
        ));
        Box::new(Run)
    }
}

impl Trial for Run {
    fn figure(&self, e: &dyn Engine) -> f64 {
        let y = f64::from(e.position(0).y);
        let t = f64::from(SECONDS);
        let expected = f64::from(Y0) - 0.5 * G * t * t;
        (y - expected).abs()
    }
}
