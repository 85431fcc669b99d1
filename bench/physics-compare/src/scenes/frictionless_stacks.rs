//! Frictionless stacks: a 3-box stack whose middle box is 10 cm off centre and a centred
//! 5-box column, every surface frictionless, for 20 s. Both are in equilibrium (each box's
//! weight is over its support), and nothing but the contact normals acts sideways. Error:
//! the largest sideways displacement of any box, m (ideal: 0).

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const H: f32 = 0.5;

/// See the module docs.
pub struct FrictionlessStacks;

struct Run {
    boxes: Vec<(BodyId, Vec3)>,
    worst: f32,
}

impl Scene for FrictionlessStacks {
    fn name(&self) -> &'static str {
        "frictionless_stacks"
    }
    fn metric(&self) -> &'static str {
        "max sideways drift of frictionless stacks (3 offset, 5 centred) over 20 s, m"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(20.0, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        e.add(&BodySpec::ground(Vec3::ZERO, 10.0).friction(0.0));
        let mut boxes = Vec::new();
        let stacks: [(f32, &[f32]); 2] = [(-3.0, &[0.0, 0.1, 0.0]), (3.0, &[0.0; 5])];
        for (x, offsets) in stacks {
            for (i, &dx) in offsets.iter().enumerate() {
                let p = Vec3::new(x + dx, H + 2.0 * H * i as f32, 0.0);
                let id =
                    e.add(&BodySpec::dynamic(ShapeSpec::Cuboid(Vec3::splat(H)), p).friction(0.0));
                boxes.push((id, p));
            }
        }
        Box::new(Run { boxes, worst: 0.0 })
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        for &(id, p0) in &self.boxes {
            let p = e.position(id);
            let d = Vec3::new(p.x - p0.x, 0.0, p.z - p0.z).length();
            self.worst = if d.is_finite() {
                self.worst.max(d)
            } else {
                f32::NAN
            };
        }
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        f64::from(self.worst)
    }
}
