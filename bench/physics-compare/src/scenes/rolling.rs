//! Rolling: a solid sphere (r = 0.5 m) released at rest on a 20° incline with μ = 1 (enough
//! to roll without slipping: tan θ ≤ 7/2 μ). Error: |a − 5/7 g sin θ| / (5/7 g sin θ), with a
//! the mean acceleration along the slope over 1 s (2 d / t²).

use onyx_physics::glam::Vec3;

use super::incline::{add_incline, on_incline};
use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const THETA_DEG: f32 = 20.0;
const MU: f32 = 1.0;
const R: f32 = 0.5;
const G: f32 = 9.81;
const T: f32 = 1.0;

/// See the module docs.
pub struct Rolling;

struct Run {
    id: BodyId,
    start: Vec3,
    down: Vec3,
}

impl Scene for Rolling {
    fn name(&self) -> &'static str {
        "rolling"
    }
    fn metric(&self) -> &'static str {
        "|a - 5/7 g sin(theta)| / (5/7 g sin(theta)), rolling sphere"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(T, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        let q = add_incline(e, Vec3::ZERO, THETA_DEG.to_radians(), MU);
        let start = on_incline(Vec3::ZERO, q, 7.0, R);
        let id = e.add(&BodySpec::dynamic(ShapeSpec::Sphere(R), start).friction(MU));
        Box::new(Run {
            id,
            start,
            down: q * Vec3::NEG_X,
        })
    }
}

impl Trial for Run {
    fn figure(&self, e: &dyn Engine) -> f64 {
        let p = e.position(self.id);
        if !p.is_finite() {
            return f64::NAN;
        }
        let d = (p - self.start).dot(self.down);
        let a = 2.0 * d / (T * T);
        let expected = 5.0 / 7.0 * G * THETA_DEG.to_radians().sin();
        f64::from(((a - expected) / expected).abs())
    }
}
