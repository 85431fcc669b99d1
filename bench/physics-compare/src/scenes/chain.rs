//! Three 20-link chains (10 cm × 50 cm × 10 cm boxes, 5 kg, ball joints end to end, the top
//! one on a ball joint to the world) hang straight down at rest, each holding a sphere of 1×,
//! 10× and 100× a link's mass on a ball joint, for 5 s (2 s quick). Error: the largest
//! stretch of a chain — the sum of its joints' anchor gaps, from the world pivot to the
//! weight, over its 10 m length, mean over the last second — as a fraction (ideal 0; the
//! goal is < 1 % at 100:1).

use onyx_physics::glam::Vec3;

use super::{add_joints, joint_gap, max_or_nan, steps_for, Scene, Size, Trial};
use crate::engine::{BodySpec, Engine, ShapeSpec, StepSettings};
use crate::joint_spec::JointSpec;

/// Links per chain.
pub const LINKS: usize = 20;
const HALF: Vec3 = Vec3::new(0.05, 0.25, 0.05);
const TOP: f32 = 12.0;
const WEIGHT_RADIUS: f32 = 0.2;
/// Weight's mass over a link's.
pub const RATIOS: [f32; 3] = [1.0, 10.0, 100.0];

/// See the module docs.
pub struct Chain;

struct Hanging {
    ratio: f32,
    joints: Vec<JointSpec>,
    stretch_sum: f64,
    samples: usize,
}

struct Run {
    chains: Vec<Hanging>,
    /// Steps before the averaging window.
    settle: usize,
    steps: usize,
}

impl Scene for Chain {
    fn name(&self) -> &'static str {
        "chain"
    }
    fn metric(&self) -> &'static str {
        "largest stretch of a hanging 20-link chain holding 1x/10x/100x a link's mass, \
         fraction of its length"
    }
    fn steps(&self, s: StepSettings, size: Size) -> usize {
        match size {
            Size::Quick => steps_for(2.0, s),
            Size::Full => steps_for(5.0, s),
        }
    }
    fn build(&self, e: &mut dyn Engine, s: StepSettings, size: Size) -> Box<dyn Trial> {
        let link_mass = 1000.0 * 8.0 * HALF.x * HALF.y * HALF.z;
        let weight_volume = 4.0 / 3.0 * std::f32::consts::PI * WEIGHT_RADIUS.powi(3);
        let chains = RATIOS
            .iter()
            .enumerate()
            .map(|(c, &ratio)| {
                let x = 3.0 * c as f32;
                let top = Vec3::new(x, TOP, 0.0);
                let mut joints = Vec::new();
                let mut above = None;
                for i in 0..LINKS {
                    let centre = top - Vec3::Y * (HALF.y * (2 * i + 1) as f32);
                    let link = e.add(&BodySpec::dynamic(ShapeSpec::Cuboid(HALF), centre));
                    let anchor_a = match above {
                        Some(_) => -Vec3::Y * HALF.y,
                        None => top,
                    };
                    joints.push(JointSpec::spherical(
                        above,
                        link,
                        Vec3::Y,
                        [anchor_a, Vec3::Y * HALF.y],
                    ));
                    above = Some(link);
                }
                let bottom = top - Vec3::Y * (2.0 * HALF.y * LINKS as f32);
                let weight = e.add(
                    &BodySpec::dynamic(
                        ShapeSpec::Sphere(WEIGHT_RADIUS),
                        bottom - Vec3::Y * WEIGHT_RADIUS,
                    )
                    .density(ratio * link_mass / weight_volume),
                );
                joints.push(JointSpec::spherical(
                    above,
                    weight,
                    Vec3::Y,
                    [-Vec3::Y * HALF.y, Vec3::Y * WEIGHT_RADIUS],
                ));
                Hanging {
                    ratio,
                    joints: add_joints(e, joints),
                    stretch_sum: 0.0,
                    samples: 0,
                }
            })
            .collect();
        let steps = self.steps(s, size);
        Box::new(Run {
            chains,
            settle: steps.saturating_sub(steps_for(1.0, s)),
            steps: 0,
        })
    }
}

impl Hanging {
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
        let length = 2.0 * HALF.y * LINKS as f32;
        for c in &mut self.chains {
            let gaps: f32 = c.joints.iter().map(|j| joint_gap(e, j)).sum();
            c.stretch_sum += f64::from(gaps / length);
            c.samples += 1;
        }
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        max_or_nan(self.chains.iter().map(Hanging::stretch))
    }
    fn detail(&self, _e: &dyn Engine) -> Option<String> {
        let parts: Vec<String> = self
            .chains
            .iter()
            .map(|c| format!("{}:1 stretch {:.3} %", c.ratio, 100.0 * c.stretch()))
            .collect();
        Some(parts.join(", "))
    }
}
