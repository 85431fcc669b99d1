//! A pile of ragdolls: 20 of them (4 quick), 11 boxes each (pelvis, torso, head, upper and
//! lower arms, thighs, shins; 1.7 m, 54 kg) on 10 joints with limits (hinges at the waist,
//! elbows and knees; ball joints with cone and twist limits at the neck, shoulders and hips),
//! lying flat in four columns of five, crossed layer on layer, dropped from up to 2 m onto
//! the ground and left to settle for 6 s (3 s quick). Error: the kinetic energy left per kg
//! of ragdoll over the last half second, J/kg (ideal 0: a settled pile). The detail gives
//! the deepest box corner below the ground over that half second, and how many boxes ended
//! more than 10 m from where they started (an explosion).

use onyx_physics::glam::{Quat, Vec3};

use super::{add_joints, steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};
use crate::joint_spec::JointSpec;

/// One part of a standing ragdoll: half extents and centre (pelvis at 1 m).
struct Part {
    half: Vec3,
    centre: Vec3,
}

const fn part(half: [f32; 3], centre: [f32; 3]) -> Part {
    Part {
        half: Vec3::from_array(half),
        centre: Vec3::from_array(centre),
    }
}

/// Pelvis, torso, head, upper arms, lower arms, thighs, shins.
const PARTS: [Part; 11] = [
    part([0.15, 0.1, 0.1], [0.0, 1.0, 0.0]),
    part([0.18, 0.2, 0.1], [0.0, 1.3, 0.0]),
    part([0.1, 0.1, 0.1], [0.0, 1.62, 0.0]),
    part([0.05, 0.15, 0.05], [-0.25, 1.33, 0.0]),
    part([0.05, 0.15, 0.05], [0.25, 1.33, 0.0]),
    part([0.045, 0.14, 0.045], [-0.25, 1.02, 0.0]),
    part([0.045, 0.14, 0.045], [0.25, 1.02, 0.0]),
    part([0.07, 0.2, 0.07], [-0.09, 0.68, 0.0]),
    part([0.07, 0.2, 0.07], [0.09, 0.68, 0.0]),
    part([0.06, 0.2, 0.06], [-0.09, 0.26, 0.0]),
    part([0.06, 0.2, 0.06], [0.09, 0.26, 0.0]),
];

/// How a joint of the ragdoll is limited.
enum Limit {
    /// A hinge about X with angle limits.
    Hinge(f32, f32),
    /// A ball joint about Y with a cone and twist limits.
    Ball(f32, f32),
}

/// (parent, child, joint point standing, limit).
const JOINTS: [(usize, usize, [f32; 3], Limit); 10] = [
    (0, 1, [0.0, 1.1, 0.0], Limit::Hinge(-0.5, 0.5)),
    (1, 2, [0.0, 1.51, 0.0], Limit::Ball(0.6, 0.8)),
    (1, 3, [-0.25, 1.48, 0.0], Limit::Ball(1.5, 1.0)),
    (1, 4, [0.25, 1.48, 0.0], Limit::Ball(1.5, 1.0)),
    (3, 5, [-0.25, 1.17, 0.0], Limit::Hinge(0.0, 2.5)),
    (4, 6, [0.25, 1.17, 0.0], Limit::Hinge(0.0, 2.5)),
    (0, 7, [-0.09, 0.89, 0.0], Limit::Ball(1.2, 0.5)),
    (0, 8, [0.09, 0.89, 0.0], Limit::Ball(1.2, 0.5)),
    (7, 9, [-0.09, 0.47, 0.0], Limit::Hinge(-2.5, 0.0)),
    (8, 10, [0.09, 0.47, 0.0], Limit::Hinge(-2.5, 0.0)),
];

/// Height of a standing ragdoll's middle, m.
const MIDDLE: f32 = 0.89;

/// See the module docs.
pub struct Ragdolls;

struct Run {
    boxes: Vec<(BodyId, Vec3, Vec3)>,
    mass: f64,
    window: usize,
    steps: usize,
    total_steps: usize,
    energy_sum: f64,
    samples: usize,
    deepest: f32,
}

/// Adds one ragdoll lying at `at` with `turn` about Y; returns its boxes (id, half, start).
fn add_ragdoll(e: &mut dyn Engine, at: Vec3, turn: f32) -> Vec<(BodyId, Vec3, Vec3)> {
    // Lying on its back: standing +Y to −Z, its front (+Z) up; then turned about Y.
    let q = Quat::from_rotation_y(turn) * Quat::from_rotation_x(-std::f32::consts::FRAC_PI_2);
    let place = |p: Vec3| at + q * (p - Vec3::Y * MIDDLE);
    let ids: Vec<(BodyId, Vec3, Vec3)> = PARTS
        .iter()
        .map(|p| {
            let start = place(p.centre);
            let id = e.add(
                &BodySpec::dynamic(ShapeSpec::Cuboid(p.half), start)
                    .rotation(q)
                    .friction(0.6),
            );
            (id, p.half, start)
        })
        .collect();
    let joints = JOINTS
        .iter()
        .map(|(parent, child, point, limit)| {
            let point = Vec3::from_array(*point);
            let anchors = [point - PARTS[*parent].centre, point - PARTS[*child].centre];
            let (a, b) = (Some(ids[*parent].0), ids[*child].0);
            match *limit {
                Limit::Hinge(lo, hi) => JointSpec::revolute(a, b, Vec3::X, anchors).limits(lo, hi),
                Limit::Ball(cone, twist) => JointSpec::spherical(a, b, Vec3::Y, anchors)
                    .cone(cone)
                    .limits(-twist, twist),
            }
        })
        .collect();
    add_joints(e, joints);
    ids
}

impl Scene for Ragdolls {
    fn name(&self) -> &'static str {
        "ragdolls"
    }
    fn metric(&self) -> &'static str {
        "pile of 20 ragdolls (11 boxes, 10 limited joints each) after 6 s: kinetic energy left, \
         J/kg"
    }
    fn steps(&self, s: StepSettings, size: Size) -> usize {
        match size {
            Size::Quick => steps_for(3.0, s),
            Size::Full => steps_for(6.0, s),
        }
    }
    fn build(&self, e: &mut dyn Engine, s: StepSettings, size: Size) -> Box<dyn Trial> {
        e.add(&BodySpec::ground(Vec3::ZERO, 20.0).friction(0.6));
        let (columns, layers) = match size {
            Size::Quick => (2, 2),
            Size::Full => (4, 5),
        };
        let mut boxes = Vec::new();
        for layer in 0..layers {
            for c in 0..columns {
                let x = if c % 2 == 0 { -1.2 } else { 1.2 };
                let z = if c < 2 { -1.2 } else { 1.2 };
                let at = Vec3::new(x, 0.5 + 0.4 * layer as f32, z);
                let turn = std::f32::consts::FRAC_PI_2 * layer as f32 + 0.1 * c as f32;
                boxes.extend(add_ragdoll(e, at, turn));
            }
        }
        let mass = boxes.iter().map(|b| f64::from(e.mass(b.0))).sum();
        let total_steps = self.steps(s, size);
        Box::new(Run {
            boxes,
            mass,
            window: steps_for(0.5, s),
            steps: 0,
            total_steps,
            energy_sum: 0.0,
            samples: 0,
            deepest: 0.0,
        })
    }
}

impl Run {
    fn energy_per_kg(&self) -> f64 {
        self.energy_sum / self.samples.max(1) as f64 / self.mass
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        self.steps += 1;
        if self.steps + self.window <= self.total_steps {
            return;
        }
        let mut energy = 0.0;
        for &(id, half, _) in &self.boxes {
            energy += e.kinetic_energy(id);
            let (p, q) = (e.position(id), e.rotation(id));
            // The lowest corner: each world axis of the box pointing down as far as it can.
            let lowest = p.y
                - [Vec3::X, Vec3::Y, Vec3::Z]
                    .iter()
                    .zip(half.to_array())
                    .map(|(&axis, h)| (q * axis).y.abs() * h)
                    .sum::<f32>();
            self.deepest = self.deepest.max(-lowest);
        }
        self.energy_sum += energy;
        self.samples += 1;
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        self.energy_per_kg()
    }
    fn detail(&self, e: &dyn Engine) -> Option<String> {
        let flown = self
            .boxes
            .iter()
            .filter(|&&(id, _, start)| {
                let d = e.position(id).distance(start);
                d.is_nan() || d > 10.0
            })
            .count();
        Some(format!(
            "{} boxes, {} joints: kinetic energy left {:.3e} J/kg, deepest corner {:.4} m below \
             the ground, {flown} boxes more than 10 m from their start",
            self.boxes.len(),
            e.joint_count(),
            self.energy_per_kg(),
            self.deepest
        ))
    }
}
