//! Rotation energy: torque-free boxes (no gravity) spun about their major, intermediate and
//! minor axes (slightly off each) and about a general axis, for 60 s. Error: the largest
//! relative change of kinetic energy or of |L| over the run (ideal: 0; both are conserved).

use onyx_physics::glam::{EulerRot, Quat, Vec3};

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const HALF: Vec3 = Vec3::new(0.5, 1.0, 1.5);

/// Body-frame spins: about x (major), y (intermediate), z (minor), and a general axis.
const SPINS: [Vec3; 4] = [
    Vec3::new(5.0, 0.05, 0.05),
    Vec3::new(0.05, 5.0, 0.05),
    Vec3::new(0.05, 0.05, 5.0),
    Vec3::new(1.0, 2.0, 3.0),
];

/// See the module docs.
pub struct RotationEnergy;

struct Run {
    boxes: Vec<(BodyId, f64, f64)>,
    worst: f64,
}

impl Scene for RotationEnergy {
    fn name(&self) -> &'static str {
        "rotation_energy"
    }
    fn metric(&self) -> &'static str {
        "max relative change of energy or |L| of torque-free tumbling boxes over 60 s"
    }
    fn steps(&self, s: StepSettings, size: Size) -> usize {
        steps_for(
            match size {
                Size::Quick => 10.0,
                Size::Full => 60.0,
            },
            s,
        )
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        let q = Quat::from_euler(EulerRot::XYZ, 0.3, -0.7, 1.1);
        let boxes = SPINS
            .iter()
            .enumerate()
            .map(|(i, &w)| {
                let id = e.add(
                    &BodySpec::dynamic(
                        ShapeSpec::Cuboid(HALF),
                        Vec3::new(10.0 * i as f32, 0.0, 0.0),
                    )
                    .rotation(q)
                    .angular_velocity(q * w)
                    .gravity_scale(0.0),
                );
                (id, e.kinetic_energy(id), e.angular_momentum(id))
            })
            .collect();
        Box::new(Run { boxes, worst: 0.0 })
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        for &(id, e0, l0) in &self.boxes {
            let de = (e.kinetic_energy(id) / e0 - 1.0).abs();
            let dl = (e.angular_momentum(id) / l0 - 1.0).abs();
            self.worst = if de.is_nan() || dl.is_nan() {
                f64::NAN
            } else {
                self.worst.max(de).max(dl)
            };
        }
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        self.worst
    }
}
