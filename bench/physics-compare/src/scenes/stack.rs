//! Vertical stack of 20 boxes (10 in quick mode) on a ground. Error: drift of the top box
//! over 1,000 steps (200 in quick mode) after a 60-step settle, m (ideal: 0).

use onyx_physics::glam::Vec3;

use super::{Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const H: f32 = 0.5;
const SETTLE: usize = 60;

/// See the module docs.
pub struct Stack;

/// Builds an `n`-box stack on its own ground at `offset`; returns the top box id.
pub fn build_stack(e: &mut dyn Engine, n: usize, offset: Vec3) -> Vec<BodyId> {
    e.add(&BodySpec::ground(offset, 5.0).friction(0.6));
    (0..n)
        .map(|i| {
            let p = offset + Vec3::new(0.0, H + 2.0 * H * i as f32, 0.0);
            e.add(&BodySpec::dynamic(ShapeSpec::Cuboid(Vec3::splat(H)), p).friction(0.6))
        })
        .collect()
}

struct Run {
    top: BodyId,
    taken: usize,
    p_settled: Vec3,
}

impl Scene for Stack {
    fn name(&self) -> &'static str {
        "stack"
    }
    fn metric(&self) -> &'static str {
        "top box drift over 1000 steps, m"
    }
    fn steps(&self, _s: StepSettings, size: Size) -> usize {
        SETTLE
            + match size {
                Size::Quick => 200,
                Size::Full => 1000,
            }
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, size: Size) -> Box<dyn Trial> {
        let n = match size {
            Size::Quick => 10,
            Size::Full => 20,
        };
        let ids = build_stack(e, n, Vec3::ZERO);
        Box::new(Run {
            top: *ids.last().expect("stack is not empty"),
            taken: 0,
            p_settled: Vec3::ZERO,
        })
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        self.taken += 1;
        if self.taken == SETTLE {
            self.p_settled = e.position(self.top);
        }
    }
    fn figure(&self, e: &dyn Engine) -> f64 {
        let p = e.position(self.top);
        if !p.is_finite() {
            return f64::NAN;
        }
        f64::from((p - self.p_settled).length())
    }
}
