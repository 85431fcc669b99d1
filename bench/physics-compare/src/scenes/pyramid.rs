//! Pyramid of boxes, 20 rows (210 boxes; 8 rows in quick mode), 1,000 steps (200 quick).
//! Error: largest displacement of any box from its start, m (ideal: ~0).

use onyx_physics::glam::Vec3;

use super::{max_displacement, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const H: f32 = 0.5;

/// See the module docs.
pub struct Pyramid;

/// Builds a `rows`-row pyramid on its own ground at `offset`; returns (id, start) pairs.
pub fn build_pyramid(e: &mut dyn Engine, rows: usize, offset: Vec3) -> Vec<(BodyId, Vec3)> {
    e.add(&BodySpec::ground(offset, rows as f32 + 5.0).friction(0.6));
    let mut out = Vec::new();
    for row in 0..rows {
        let n = rows - row;
        for i in 0..n {
            let x = (i as f32 - (n - 1) as f32 * 0.5) * 2.0 * H * 1.02;
            let p = offset + Vec3::new(x, H + row as f32 * 2.0 * H, 0.0);
            let id = e.add(&BodySpec::dynamic(ShapeSpec::Cuboid(Vec3::splat(H)), p).friction(0.6));
            out.push((id, p));
        }
    }
    out
}

struct Run {
    boxes: Vec<(BodyId, Vec3)>,
}

impl Scene for Pyramid {
    fn name(&self) -> &'static str {
        "pyramid"
    }
    fn metric(&self) -> &'static str {
        "largest box displacement after 1000 steps, m"
    }
    fn steps(&self, _s: StepSettings, size: Size) -> usize {
        match size {
            Size::Quick => 200,
            Size::Full => 1000,
        }
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, size: Size) -> Box<dyn Trial> {
        let rows = match size {
            Size::Quick => 8,
            Size::Full => 20,
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
