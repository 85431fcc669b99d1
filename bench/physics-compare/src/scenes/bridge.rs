//! A suspension bridge: 50 planks (50 cm × 10 cm × 1 m, 50 kg) on hinges edge to edge, the
//! two end planks on hinges to the world 24 m apart — 25 m of bridge, so it hangs with slack.
//! It starts as a circular arc through the two anchors and settles toward its catenary over
//! 5 s (3 s quick). Error: its stretch — the sum of the 51 hinges' anchor gaps over its 25 m
//! length, mean over the last second — as a fraction (ideal 0). The detail gives the sag at
//! mid-span and the fastest plank at the end (a bridge that does not settle shows there).

use onyx_physics::glam::{Quat, Vec3};

use super::{add_joints, joint_gap, steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};
use crate::joint_spec::JointSpec;

/// Planks.
pub const PLANKS: usize = 50;
const HALF: Vec3 = Vec3::new(0.25, 0.05, 0.5);
/// Distance between the two world anchors, m.
pub const SPAN: f32 = 24.0;
const HEIGHT: f32 = 10.0;

/// See the module docs.
pub struct Bridge;

struct Run {
    planks: Vec<BodyId>,
    joints: Vec<JointSpec>,
    settle: usize,
    steps: usize,
    stretch_sum: f64,
    samples: usize,
}

/// Half the angle the arc subtends: `2 R sin(α / n) = plank length` and `2 R sin α = span`.
fn arc_half_angle() -> f32 {
    let n = PLANKS as f32;
    let span = |a: f32| 2.0 * HALF.x * a.sin() / (a / n).sin();
    let (mut lo, mut hi) = (1e-4f32, std::f32::consts::FRAC_PI_2);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        // The span shrinks as the arc deepens.
        if span(mid) > SPAN {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

impl Scene for Bridge {
    fn name(&self) -> &'static str {
        "bridge"
    }
    fn metric(&self) -> &'static str {
        "stretch of a 50-plank hinged bridge (25 m hung over 24 m), fraction of its length"
    }
    fn steps(&self, s: StepSettings, size: Size) -> usize {
        match size {
            Size::Quick => steps_for(3.0, s),
            Size::Full => steps_for(5.0, s),
        }
    }
    fn build(&self, e: &mut dyn Engine, s: StepSettings, size: Size) -> Box<dyn Trial> {
        let alpha = arc_half_angle();
        let n = PLANKS as f32;
        let radius = HALF.x / (alpha / n).sin();
        let centre = Vec3::new(0.5 * SPAN, HEIGHT + radius * alpha.cos(), 0.0);
        let point = |k: usize| {
            let t = -alpha + 2.0 * alpha * k as f32 / n;
            centre + radius * Vec3::new(t.sin(), -t.cos(), 0.0)
        };
        let (left, right) = (-Vec3::X * HALF.x, Vec3::X * HALF.x);
        let mut planks = Vec::new();
        let mut joints = Vec::new();
        for k in 0..PLANKS {
            let (p0, p1) = (point(k), point(k + 1));
            let d = p1 - p0;
            let plank = e.add(
                &BodySpec::dynamic(ShapeSpec::Cuboid(HALF), 0.5 * (p0 + p1))
                    .rotation(Quat::from_rotation_z(d.y.atan2(d.x))),
            );
            let joint = match planks.last() {
                Some(&prev) => JointSpec::revolute(Some(prev), plank, Vec3::Z, [right, left]),
                None => JointSpec::revolute(None, plank, Vec3::Z, [p0, left]),
            };
            joints.push(joint);
            planks.push(plank);
        }
        let last = *planks.last().expect("planks");
        joints.push(JointSpec::revolute(
            None,
            last,
            Vec3::Z,
            [point(PLANKS), right],
        ));
        let steps = self.steps(s, size);
        Box::new(Run {
            planks,
            joints: add_joints(e, joints),
            settle: steps.saturating_sub(steps_for(1.0, s)),
            steps: 0,
            stretch_sum: 0.0,
            samples: 0,
        })
    }
}

impl Run {
    fn stretch(&self) -> f64 {
        self.stretch_sum / self.samples.max(1) as f64
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        self.steps += 1;
        if self.steps <= self.settle {
            return;
        }
        let gaps: f32 = self.joints.iter().map(|j| joint_gap(e, j)).sum();
        self.stretch_sum += f64::from(gaps / (2.0 * HALF.x * PLANKS as f32));
        self.samples += 1;
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        self.stretch()
    }
    fn detail(&self, e: &dyn Engine) -> Option<String> {
        let mid = e.position(self.planks[PLANKS / 2]).y;
        let fastest = self
            .planks
            .iter()
            .map(|&p| e.velocity(p).length())
            .fold(0.0f32, f32::max);
        Some(format!(
            "stretch {:.4} %, mid-span sag {:.3} m, fastest plank at the end {:.3} m/s",
            100.0 * self.stretch(),
            HEIGHT - mid,
            fastest
        ))
    }
}
