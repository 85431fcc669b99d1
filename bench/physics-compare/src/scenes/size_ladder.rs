//! Size ladder: balls of 1 mm, 1 cm, 10 cm, 1 m, 10 m, 100 m and 1 km diameter, each resting
//! on a dynamic box (4 diameters wide, 2 tall) on the ground, started exactly touching.
//! Error: the largest resting penetration of a ball into its box after 3 s, as a fraction of
//! the ball's diameter (ideal: 0; the bound: 0.05).

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const DIAMETERS: [f32; 7] = [0.001, 0.01, 0.1, 1.0, 10.0, 100.0, 1000.0];

/// See the module docs.
pub struct SizeLadder;

struct Run {
    /// (ball, box, diameter).
    pairs: Vec<(BodyId, BodyId, f32)>,
}

impl Scene for SizeLadder {
    fn name(&self) -> &'static str {
        "size_ladder"
    }
    fn metric(&self) -> &'static str {
        "max resting penetration of 1 mm ... 1 km balls on boxes, fraction of diameter"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(3.0, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        e.add(&BodySpec::ground(Vec3::ZERO, 20_000.0));
        let mut x = 0.0f32;
        let pairs = DIAMETERS
            .iter()
            .map(|&d| {
                let r = 0.5 * d;
                let half = Vec3::new(2.0 * d, d, 2.0 * d);
                x += 2.0 * half.x + 1.0;
                let bx = e.add(&BodySpec::dynamic(
                    ShapeSpec::Cuboid(half),
                    Vec3::new(x, half.y, 0.0),
                ));
                let ball = e.add(&BodySpec::dynamic(
                    ShapeSpec::Sphere(r),
                    Vec3::new(x, 2.0 * half.y + r, 0.0),
                ));
                x += 2.0 * half.x;
                (ball, bx, d)
            })
            .collect();
        Box::new(Run { pairs })
    }
}

impl Trial for Run {
    fn figure(&self, e: &dyn Engine) -> f64 {
        let mut worst = 0.0f64;
        for &(ball, bx, d) in &self.pairs {
            let (pb, pq) = (e.position(ball), e.position(bx));
            if !(pb.is_finite() && pq.is_finite()) {
                return f64::NAN;
            }
            // Box top at centre + d; ball centre should be d/2 above it.
            let pen = (pq.y + d + 0.5 * d) - pb.y;
            worst = worst.max(f64::from(pen / d));
        }
        worst
    }
}
