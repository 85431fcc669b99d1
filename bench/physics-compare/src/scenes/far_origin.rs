//! Far from the origin: a 5-box stack and a 6-row pyramid built at the origin and at offsets
//! 1e4, 1e5, 1e6 m (x and z) in the same world. Error: the largest difference between a
//! copy's displacement (relative to its offset) and the origin copy's, after 300 steps, m.

use onyx_physics::glam::Vec3;

use super::pyramid::build_pyramid;
use super::stack::build_stack;
use super::{Scene, Size, Trial};
use crate::engine::{BodyId, Engine, StepSettings};

/// Offsets swept, m.
pub const OFFSETS: [f32; 4] = [0.0, 1.0e4, 1.0e5, 1.0e6];

/// See the module docs.
pub struct FarOrigin;

struct Copy {
    offset: Vec3,
    bodies: Vec<(BodyId, Vec3)>,
}

struct Run {
    copies: Vec<Copy>,
}

impl Scene for FarOrigin {
    fn name(&self) -> &'static str {
        "far_origin"
    }
    fn metric(&self) -> &'static str {
        "max |drift at offset - drift at origin| over 1e4..1e6 m, m"
    }
    fn steps(&self, _s: StepSettings, size: Size) -> usize {
        match size {
            Size::Quick => 120,
            Size::Full => 300,
        }
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, size: Size) -> Box<dyn Trial> {
        let rows = match size {
            Size::Quick => 4,
            Size::Full => 6,
        };
        let copies = OFFSETS
            .iter()
            .map(|&o| {
                let offset = Vec3::new(o, 0.0, -o);
                let mut bodies: Vec<(BodyId, Vec3)> = build_stack(e, 5, offset)
                    .into_iter()
                    .map(|id| (id, e.position(id)))
                    .collect();
                bodies.extend(build_pyramid(e, rows, offset + Vec3::new(0.0, 0.0, 5.0)));
                Copy { offset, bodies }
            })
            .collect();
        Box::new(Run { copies })
    }
}

/// Per-offset drift difference against the origin copy (index 0 is the origin itself).
fn diffs(run: &Run, e: &dyn Engine) -> Vec<f64> {
    let origin = &run.copies[0];
    run.copies
        .iter()
        .map(|c| {
            let mut worst = 0.0f64;
            for (&(id, p0), &(oid, op0)) in c.bodies.iter().zip(&origin.bodies) {
                let p = e.position(id);
                if !p.is_finite() {
                    return f64::NAN;
                }
                // Work in f64 so the measure itself does not lose the offset's precision.
                let d = [0usize, 1, 2].map(|k| {
                    let local = f64::from(p[k]) - f64::from(c.offset[k]);
                    let local0 = f64::from(p0[k]) - f64::from(c.offset[k]);
                    let o = f64::from(e.position(oid)[k]) - f64::from(op0[k]);
                    (local - local0) - o
                });
                worst = worst.max((d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt());
            }
            worst
        })
        .collect()
}

impl Trial for Run {
    fn figure(&self, e: &dyn Engine) -> f64 {
        diffs(self, e).into_iter().fold(0.0, |a, b| {
            if b.is_nan() || a.is_nan() {
                f64::NAN
            } else {
                a.max(b)
            }
        })
    }
}
