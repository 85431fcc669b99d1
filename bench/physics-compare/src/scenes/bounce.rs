//! Bounce ladder: spheres with restitution e = 0.3, 0.5, 0.7, 0.9 dropped from 2 m (gap
//! below the sphere) onto a ground with e = 0 (max rule: the ball's e applies). Error: mean
//! over the ladder of |h1/h0 − e²|, with h1 the first rebound apex gap.

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const E: [f32; 4] = [0.3, 0.5, 0.7, 0.9];
const H0: f32 = 2.0;
const R: f32 = 0.25;

/// See the module docs.
pub struct BounceLadder;

struct Ball {
    id: BodyId,
    e: f32,
    bounced: bool,
    apex: f32,
    prev_vy: f32,
}

struct Run {
    balls: Vec<Ball>,
}

impl Scene for BounceLadder {
    fn name(&self) -> &'static str {
        "bounce"
    }
    fn metric(&self) -> &'static str {
        "mean |h1/h0 - e^2| (rebound apex ratio)"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        // Fall ~0.64 s, rise ≤ 0.58 s.
        steps_for(1.5, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        e.add(&BodySpec::ground(Vec3::ZERO, 10.0).restitution(0.0));
        let balls = E
            .iter()
            .enumerate()
            .map(|(i, &rest)| {
                let p = Vec3::new(-3.0 + 2.0 * i as f32, H0 + R, 0.0);
                let id = e.add(&BodySpec::dynamic(ShapeSpec::Sphere(R), p).restitution(rest));
                Ball {
                    id,
                    e: rest,
                    bounced: false,
                    apex: 0.0,
                    prev_vy: 0.0,
                }
            })
            .collect();
        Box::new(Run { balls })
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        for b in &mut self.balls {
            let vy = e.velocity(b.id).y;
            let y = e.position(b.id).y - R;
            if !b.bounced && b.prev_vy < 0.0 && vy > 0.0 {
                b.bounced = true;
            }
            if b.bounced {
                b.apex = b.apex.max(y);
            }
            b.prev_vy = vy;
        }
    }
    fn figure(&self, e: &dyn Engine) -> f64 {
        let mut sum = 0.0;
        for b in &self.balls {
            if !e.position(b.id).is_finite() {
                return f64::NAN;
            }
            sum += f64::from((b.apex / H0 - b.e * b.e).abs());
        }
        sum / self.balls.len() as f64
    }
}
