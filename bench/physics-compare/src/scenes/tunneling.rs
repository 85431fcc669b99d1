//! Tunneling: bullets (r = 5 cm spheres, CCD on, no gravity) fired at 50…500 m/s at a fixed
//! wall 10 cm thick. Error: share of bullets found beyond the wall after 0.25 s (ideal: 0).

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const WALL_HALF: f32 = 0.05;
const R: f32 = 0.05;

/// Bullet speeds, m/s.
#[must_use]
pub fn speeds(size: Size) -> Vec<f32> {
    let n = match size {
        Size::Quick => 4,
        Size::Full => 10,
    };
    (0..n)
        .map(|i| 50.0 + 450.0 * i as f32 / (n - 1) as f32)
        .collect()
}

/// See the module docs.
pub struct Tunneling;

struct Run {
    bullets: Vec<BodyId>,
}

impl Scene for Tunneling {
    fn name(&self) -> &'static str {
        "tunneling"
    }
    fn metric(&self) -> &'static str {
        "share of bullets (50-500 m/s, CCD) through a 10 cm wall"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(0.25, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, size: Size) -> Box<dyn Trial> {
        let v = speeds(size);
        let width = v.len() as f32 + 2.0;
        e.add(&BodySpec::fixed(
            ShapeSpec::Cuboid(Vec3::new(WALL_HALF, 2.0, width)),
            Vec3::ZERO,
        ));
        let bullets = v
            .iter()
            .enumerate()
            .map(|(i, &speed)| {
                let z = -width + 1.0 + 2.0 * i as f32;
                e.add(
                    &BodySpec::dynamic(ShapeSpec::Sphere(R), Vec3::new(-3.0, 0.0, z))
                        .velocity(Vec3::new(speed, 0.0, 0.0))
                        .gravity_scale(0.0)
                        .density(7800.0)
                        .ccd(true),
                )
            })
            .collect();
        Box::new(Run { bullets })
    }
}

impl Trial for Run {
    fn figure(&self, e: &dyn Engine) -> f64 {
        let mut through = 0usize;
        for &b in &self.bullets {
            let x = e.position(b).x;
            if !x.is_finite() {
                return f64::NAN;
            }
            if x > WALL_HALF {
                through += 1;
            }
        }
        through as f64 / self.bullets.len() as f64
    }
}
