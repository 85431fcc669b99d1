//! Big pyramid: 100 rows (5,050 boxes; 15 rows = 120 boxes quick), 500 steps (100 quick).
//! Error: largest displacement of any box from its start, m (ideal: ~0).

use onyx_physics::glam::Vec3;

use super::pyramid::build_pyramid;
use super::{max_displacement, Scene, Size, Trial};
use crate::engine::{BodyId, Engine, StepSettings};

/// See the module docs.
pub struct BigPyramid;

struct Run {
    boxes: Vec<(BodyId, Vec3)>,
}

impl Scene for BigPyramid {
    fn name(&self) -> &'static str {
        "big_pyramid"
    }
    fn metric(&self) -> &'static str {
        "largest box displacement after 500 steps (100-row pyramid), m"
    }
    fn steps(&self, _s: StepSettings, size: Size) -> usize {
        match size {
            Size::Quick => 100,
            Size::Full => 500,
        }
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, size: Size) -> Box<dyn Trial> {
        let rows = match size {
            Size::Quick => 15,
            Size::Full => 100,
        };
        Box::new(Run {
            boxes: build_pyramid(e, rows, Vec3::ZERO),
        })
    }
}

impl Trial for Run {
    fn figure(&self, e: &dyn Engine) -> f64 {
        max_displacement(e, &self.boxes)
    }
}
