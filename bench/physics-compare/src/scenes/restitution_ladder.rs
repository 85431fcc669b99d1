//! Restitution ladder with threshold 0: balls with e = 0.5, 0.8 and 1 (ground e = 0, max
//! rule) dropped from 2 m, 40 rebounds each, with the bounce threshold at 0 where the
//! engine has one (rapier 0.36 has none). Error: the largest |h_k / h0 − e^(2k)| over the
//! rebounds k (ideal: 0).

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const E: [f32; 3] = [0.5, 0.8, 1.0];
const H0: f32 = 2.0;
const R: f32 = 0.1;
const REBOUNDS: usize = 40;

/// See the module docs.
pub struct RestitutionLadder;

struct Ball {
    id: BodyId,
    e: f32,
    rising: bool,
    apex: f32,
    prev_vy: f32,
    apexes: Vec<f32>,
}

struct Run {
    balls: Vec<Ball>,
}

impl Scene for RestitutionLadder {
    fn name(&self) -> &'static str {
        "restitution_ladder"
    }
    fn metric(&self) -> &'static str {
        "max |h_k/h0 - e^2k| over 40 rebounds, e = 0.5/0.8/1, threshold 0"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        // 40 cycles of an e = 1 ball from 2 m (1.28 s each), and the time each impact spends
        // resting inside its step (up to a step each).
        steps_for(60.0, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        e.set_restitution_threshold(0.0);
        e.add(
            &BodySpec::ground(Vec3::ZERO, 10.0)
                .restitution(0.0)
                .friction(0.0),
        );
        let balls = E
            .iter()
            .enumerate()
            .map(|(i, &rest)| {
                let p = Vec3::new(-2.0 + 2.0 * i as f32, H0 + R, 0.0);
                let id = e.add(
                    &BodySpec::dynamic(ShapeSpec::Sphere(R), p)
                        .restitution(rest)
                        .friction(0.0),
                );
                Ball {
                    id,
                    e: rest,
                    rising: false,
                    apex: 0.0,
                    prev_vy: 0.0,
                    apexes: Vec::new(),
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
            if b.prev_vy <= 0.0 && vy > 0.0 {
                b.rising = true;
                b.apex = y;
            }
            if b.rising {
                b.apex = b.apex.max(y);
                if vy <= 0.0 {
                    b.rising = false;
                    if b.apexes.len() < REBOUNDS {
                        b.apexes.push(b.apex);
                    }
                }
            }
            b.prev_vy = vy;
        }
    }
    fn figure(&self, e: &dyn Engine) -> f64 {
        let mut worst = 0.0f64;
        for b in &self.balls {
            if !e.position(b.id).is_finite() {
                return f64::NAN;
            }
            // Rebounds that never came count as height 0.
            for k in 0..REBOUNDS {
                let expected = f64::from(b.e).powi(2 * (k as i32 + 1));
                // Rebounds lower than 1 mm are below what a step resolves.
                if expected * f64::from(H0) < 1e-3 {
                    break;
                }
                let h = b.apexes.get(k).copied().unwrap_or(0.0);
                worst = worst.max((f64::from(h / H0) - expected).abs());
            }
        }
        worst
    }
}
