//! Mass-ratio ladder: a 1 m cube resting on a 0.5 m cube on the ground, heavy to light
//! 1:1, 10:1, 100:1 and 1000:1 (one pair each), started exactly touching. Error: the largest
//! sinking of a heavy cube below where it was placed, over 3 s, m (ideal: 0).

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const RATIOS: [f32; 4] = [1.0, 10.0, 100.0, 1000.0];
const LIGHT_HALF: f32 = 0.25;
const HEAVY_HALF: f32 = 0.5;

/// See the module docs.
pub struct MassRatioLadder;

struct Run {
    heavy: Vec<(BodyId, f32)>,
    worst: f32,
}

impl Scene for MassRatioLadder {
    fn name(&self) -> &'static str {
        "mass_ratio_ladder"
    }
    fn metric(&self) -> &'static str {
        "max sinking of a heavy cube on a light one, 1:1 ... 1000:1, m"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(3.0, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        e.add(&BodySpec::ground(Vec3::ZERO, 20.0).friction(0.6));
        let light_mass = 1000.0 * (2.0 * LIGHT_HALF).powi(3);
        let heavy_volume = (2.0 * HEAVY_HALF).powi(3);
        let heavy = RATIOS
            .iter()
            .enumerate()
            .map(|(i, &ratio)| {
                let x = -6.0 + 4.0 * i as f32;
                e.add(
                    &BodySpec::dynamic(
                        ShapeSpec::Cuboid(Vec3::splat(LIGHT_HALF)),
                        Vec3::new(x, LIGHT_HALF, 0.0),
                    )
                    .friction(0.6),
                );
                let y = 2.0 * LIGHT_HALF + HEAVY_HALF;
                let id = e.add(
                    &BodySpec::dynamic(
                        ShapeSpec::Cuboid(Vec3::splat(HEAVY_HALF)),
                        Vec3::new(x, y, 0.0),
                    )
                    .density(ratio * light_mass / heavy_volume)
                    .friction(0.6),
                );
                (id, y)
            })
            .collect();
        Box::new(Run { heavy, worst: 0.0 })
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        for &(id, y0) in &self.heavy {
            let y = e.position(id).y;
            self.worst = if y.is_finite() {
                self.worst.max(y0 - y)
            } else {
                f32::NAN
            };
        }
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        f64::from(self.worst)
    }
}
