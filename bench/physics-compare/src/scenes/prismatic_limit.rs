//! Prismatic limits under load: two vertical sliders on the world, for 3 s (2 s quick).
//! (a) A 1 m cube (1000 kg) let go at its upper limit falls 1 m onto its lower limit
//! (4.4 m/s) and rests there. (b) An 8 kg carriage resting on its lower limit carries an
//! 800 kg sphere hung 1 m below it on a ball joint (100:1). Error: the largest violation of
//! a lower limit over the run — how far a slider got below it — m (ideal 0).

use onyx_physics::glam::Vec3;

use super::{add_joints, max_or_nan, steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};
use crate::joint_spec::JointSpec;

const TOP: f32 = 4.0;
const CARRIAGE_HALF: f32 = 0.1;
const WEIGHT_RADIUS: f32 = 0.3;
const WEIGHT_MASS: f32 = 800.0;

/// See the module docs.
pub struct PrismaticLimit;

/// One slider: its body, where its anchor on the world is, its lower limit, and the worst
/// violation so far.
struct Slider {
    name: &'static str,
    body: BodyId,
    rail: Vec3,
    lower: f32,
    worst: f32,
    last: f32,
}

struct Run {
    sliders: Vec<Slider>,
}

impl Scene for PrismaticLimit {
    fn name(&self) -> &'static str {
        "prismatic_limit"
    }
    fn metric(&self) -> &'static str {
        "largest violation of a slider's lower limit: a 1000 kg cube dropped 1 m onto it, an \
         8 kg carriage holding 800 kg, m"
    }
    fn steps(&self, s: StepSettings, size: Size) -> usize {
        match size {
            Size::Quick => steps_for(2.0, s),
            Size::Full => steps_for(3.0, s),
        }
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        let rail_a = Vec3::new(0.0, TOP, 0.0);
        let cube = e.add(&BodySpec::dynamic(
            ShapeSpec::Cuboid(Vec3::splat(0.5)),
            rail_a,
        ));
        let rail_b = Vec3::new(4.0, TOP, 0.0);
        let lower_b = -0.5;
        let carriage_at = rail_b + Vec3::Y * lower_b;
        let carriage = e.add(&BodySpec::dynamic(
            ShapeSpec::Cuboid(Vec3::splat(CARRIAGE_HALF)),
            carriage_at,
        ));
        let volume = 4.0 / 3.0 * std::f32::consts::PI * WEIGHT_RADIUS.powi(3);
        let weight = e.add(
            &BodySpec::dynamic(
                ShapeSpec::Sphere(WEIGHT_RADIUS),
                carriage_at - Vec3::Y * (1.0 + WEIGHT_RADIUS),
            )
            .density(WEIGHT_MASS / volume),
        );
        add_joints(
            e,
            vec![
                JointSpec::prismatic(None, cube, Vec3::Y, [rail_a, Vec3::ZERO]).limits(-1.0, 0.0),
                JointSpec::prismatic(None, carriage, Vec3::Y, [rail_b, Vec3::ZERO])
                    .limits(lower_b, 0.5),
                JointSpec::spherical(
                    Some(carriage),
                    weight,
                    Vec3::Y,
                    [-Vec3::Y * 1.0, Vec3::Y * WEIGHT_RADIUS],
                ),
            ],
        );
        Box::new(Run {
            sliders: vec![
                Slider {
                    name: "dropped cube",
                    body: cube,
                    rail: rail_a,
                    lower: -1.0,
                    worst: 0.0,
                    last: 0.0,
                },
                Slider {
                    name: "loaded carriage",
                    body: carriage,
                    rail: rail_b,
                    lower: lower_b,
                    worst: 0.0,
                    last: 0.0,
                },
            ],
        })
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        for s in &mut self.sliders {
            // The slider's translation along its (vertical) axis; its anchor is its centre.
            let x = e.position(s.body).y - s.rail.y;
            let v = s.lower - x;
            s.last = v;
            s.worst = if x.is_finite() && !s.worst.is_nan() {
                s.worst.max(v)
            } else {
                f32::NAN
            };
        }
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        max_or_nan(self.sliders.iter().map(|s| f64::from(s.worst)))
    }
    fn detail(&self, _e: &dyn Engine) -> Option<String> {
        let parts: Vec<String> = self
            .sliders
            .iter()
            .map(|s| {
                format!(
                    "{}: worst {:.3e} m, at the end {:.3e} m",
                    s.name, s.worst, s.last
                )
            })
            .collect();
        Some(parts.join("; "))
    }
}
