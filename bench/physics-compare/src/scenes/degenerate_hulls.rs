//! Degenerate hulls resting on a ground: a 1 × 1 m plate 2 mm thick, a thin triangular wedge
//! (1 m sides, 2 mm thick), a cube hull with extra coplanar points on every face, and two
//! cube hulls stacked with exactly coincident faces, all started exactly touching; 2 s.
//! Error: largest displacement from the start, m, plus 1 per GJK/EPA failure reported by the
//! engine (Onyx only: gjk_not_converged + epa_failures; rapier does not report them).

use onyx_physics::glam::Vec3;

use super::{max_displacement, steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const T: f32 = 0.001;

static PLATE: [Vec3; 8] = [
    Vec3::new(-0.5, -T, -0.5),
    Vec3::new(0.5, -T, -0.5),
    Vec3::new(0.5, -T, 0.5),
    Vec3::new(-0.5, -T, 0.5),
    Vec3::new(-0.5, T, -0.5),
    Vec3::new(0.5, T, -0.5),
    Vec3::new(0.5, T, 0.5),
    Vec3::new(-0.5, T, 0.5),
];

static WEDGE: [Vec3; 6] = [
    Vec3::new(-0.5, -T, -0.288_675),
    Vec3::new(0.5, -T, -0.288_675),
    Vec3::new(0.0, -T, 0.577_35),
    Vec3::new(-0.5, T, -0.288_675),
    Vec3::new(0.5, T, -0.288_675),
    Vec3::new(0.0, T, 0.577_35),
];

static CUBE: [Vec3; 8] = [
    Vec3::new(-0.5, -0.5, -0.5),
    Vec3::new(0.5, -0.5, -0.5),
    Vec3::new(0.5, -0.5, 0.5),
    Vec3::new(-0.5, -0.5, 0.5),
    Vec3::new(-0.5, 0.5, -0.5),
    Vec3::new(0.5, 0.5, -0.5),
    Vec3::new(0.5, 0.5, 0.5),
    Vec3::new(-0.5, 0.5, 0.5),
];

/// Cube corners plus the centre of every face and the middle of every bottom/top edge.
static CUBE_COPLANAR: [Vec3; 22] = [
    Vec3::new(-0.5, -0.5, -0.5),
    Vec3::new(0.5, -0.5, -0.5),
    Vec3::new(0.5, -0.5, 0.5),
    Vec3::new(-0.5, -0.5, 0.5),
    Vec3::new(-0.5, 0.5, -0.5),
    Vec3::new(0.5, 0.5, -0.5),
    Vec3::new(0.5, 0.5, 0.5),
    Vec3::new(-0.5, 0.5, 0.5),
    Vec3::new(0.0, -0.5, 0.0),
    Vec3::new(0.0, 0.5, 0.0),
    Vec3::new(-0.5, 0.0, 0.0),
    Vec3::new(0.5, 0.0, 0.0),
    Vec3::new(0.0, 0.0, -0.5),
    Vec3::new(0.0, 0.0, 0.5),
    Vec3::new(0.0, -0.5, -0.5),
    Vec3::new(0.0, -0.5, 0.5),
    Vec3::new(-0.5, -0.5, 0.0),
    Vec3::new(0.5, -0.5, 0.0),
    Vec3::new(0.0, 0.5, -0.5),
    Vec3::new(0.0, 0.5, 0.5),
    Vec3::new(-0.5, 0.5, 0.0),
    Vec3::new(0.5, 0.5, 0.0),
];

/// See the module docs.
pub struct DegenerateHulls;

struct Run {
    bodies: Vec<(BodyId, Vec3)>,
}

impl Scene for DegenerateHulls {
    fn name(&self) -> &'static str {
        "degenerate_hulls"
    }
    fn metric(&self) -> &'static str {
        "max displacement of resting flat/coincident hulls (m) + GJK/EPA failures (onyx)"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(2.0, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        e.add(&BodySpec::ground(Vec3::ZERO, 10.0));
        let placed: [(&'static [Vec3], Vec3); 5] = [
            (&PLATE, Vec3::new(-3.0, T, 0.0)),
            (&WEDGE, Vec3::new(-1.5, T, 0.0)),
            (&CUBE_COPLANAR, Vec3::new(0.0, 0.5, 0.0)),
            (&CUBE, Vec3::new(2.0, 0.5, 0.0)),
            (&CUBE, Vec3::new(2.0, 1.5, 0.0)),
        ];
        let bodies = placed
            .iter()
            .map(|&(pts, p)| (e.add(&BodySpec::dynamic(ShapeSpec::Hull(pts), p)), p))
            .collect();
        Box::new(Run { bodies })
    }
}

impl Trial for Run {
    fn figure(&self, e: &dyn Engine) -> f64 {
        let failures = e.narrowphase_tally().map_or(0, |t| t.failures()) as f64;
        max_displacement(e, &self.bodies) + failures
    }
    fn detail(&self, e: &dyn Engine) -> Option<String> {
        e.narrowphase_tally().map(|t| t.to_string())
    }
}
