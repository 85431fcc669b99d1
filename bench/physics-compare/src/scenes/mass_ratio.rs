//! High mass ratio: a heavy plank (400× the mass of each support) resting on two light cubes.
//! Error: the plank's sinking below its ideal resting height (total penetration of the
//! plank–cube–ground chain), the largest over the last second of 2 s, m (ideal: ~slop).

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

/// Mass ratio heavy : light.
pub const RATIO: f32 = 400.0;
const LIGHT_HALF: f32 = 0.25;
const LIGHT_DENSITY: f32 = 100.0;
const PLANK: Vec3 = Vec3::new(1.25, 0.25, 0.25);

/// See the module docs.
pub struct MassRatio;

struct Run {
    plank: BodyId,
    ideal_y: f32,
    taken: usize,
    from: usize,
    worst: f32,
}

impl Scene for MassRatio {
    fn name(&self) -> &'static str {
        "mass_ratio"
    }
    fn metric(&self) -> &'static str {
        "plank sinking below ideal (400:1 on light cubes), max over last 1 s, m"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(2.0, s)
    }
    fn build(&self, e: &mut dyn Engine, s: StepSettings, size: Size) -> Box<dyn Trial> {
        e.add(&BodySpec::ground(Vec3::ZERO, 10.0).friction(0.6));
        for x in [-0.9f32, 0.9] {
            e.add(
                &BodySpec::dynamic(
                    ShapeSpec::Cuboid(Vec3::splat(LIGHT_HALF)),
                    Vec3::new(x, LIGHT_HALF, 0.0),
                )
                .density(LIGHT_DENSITY)
                .friction(0.6),
            );
        }
        let light_mass = LIGHT_DENSITY * 8.0 * LIGHT_HALF.powi(3);
        let plank_volume = 8.0 * PLANK.x * PLANK.y * PLANK.z;
        let ideal_y = 2.0 * LIGHT_HALF + PLANK.y;
        let plank = e.add(
            &BodySpec::dynamic(ShapeSpec::Cuboid(PLANK), Vec3::new(0.0, ideal_y, 0.0))
                .density(RATIO * light_mass / plank_volume)
                .friction(0.6),
        );
        let total = self.steps(s, size);
        Box::new(Run {
            plank,
            ideal_y,
            taken: 0,
            from: total.saturating_sub(steps_for(1.0, s)),
            worst: 0.0,
        })
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        self.taken += 1;
        let y = e.position(self.plank).y;
        let sink = if y.is_finite() {
            (self.ideal_y - y).max(0.0)
        } else {
            f32::NAN
        };
        if self.taken > self.from || sink.is_nan() {
            self.worst = if sink.is_nan() {
                f32::NAN
            } else {
                self.worst.max(sink)
            };
        }
    }
    fn figure(&self, e: &dyn Engine) -> f64 {
        if !e.position(self.plank).is_finite() {
            return f64::NAN;
        }
        f64::from(self.worst)
    }
}
