//! A hinge motor: a 1 m × 1 m × 20 cm plate (200 kg, 33.3 kg·m² about its axis) on a hinge
//! to the world through its centre, driven from rest toward 2π rad/s with at most 100 N·m,
//! for 4 s (3 s quick). Exactly, it accelerates at τ/I and reaches 99 % of the target speed
//! at `0.99 I ω / τ` = 2.073 s, then holds it. Error: the larger of the relative error of
//! that time and the relative speed error over the last second (ideal 0).

use onyx_physics::glam::Vec3;

use super::{add_joints, steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};
use crate::joint_spec::JointSpec;

const HALF: Vec3 = Vec3::new(0.5, 0.5, 0.1);
const SPEED: f64 = std::f64::consts::TAU;
const TORQUE: f64 = 100.0;
/// The share of the target speed whose time of arrival is measured.
const REACHED: f64 = 0.99;

/// See the module docs.
pub struct HingeMotor;

struct Run {
    plate: BodyId,
    dt: f64,
    steps: usize,
    /// Steps before the speed-averaging window.
    settle: usize,
    last: f64,
    reached_at: Option<f64>,
    speed_error_sum: f64,
    samples: usize,
}

/// Inertia of the plate about its hinge (Z), kg·m².
fn inertia() -> f64 {
    let (x, y, z) = (
        2.0 * f64::from(HALF.x),
        2.0 * f64::from(HALF.y),
        2.0 * f64::from(HALF.z),
    );
    let m = 1000.0 * x * y * z;
    m * (x * x + y * y) / 12.0
}

/// The exact time to reach [`REACHED`] of the target speed, s.
fn exact_time() -> f64 {
    REACHED * inertia() * SPEED / TORQUE
}

impl Scene for HingeMotor {
    fn name(&self) -> &'static str {
        "hinge_motor"
    }
    fn metric(&self) -> &'static str {
        "hinge motor to 2π rad/s at 100 N·m: larger relative error of the time to 99 % of the \
         speed and of the held speed, fraction"
    }
    fn steps(&self, s: StepSettings, size: Size) -> usize {
        match size {
            Size::Quick => steps_for(3.0, s),
            Size::Full => steps_for(4.0, s),
        }
    }
    fn build(&self, e: &mut dyn Engine, s: StepSettings, size: Size) -> Box<dyn Trial> {
        let centre = Vec3::new(0.0, 2.0, 0.0);
        let plate = e.add(&BodySpec::dynamic(ShapeSpec::Cuboid(HALF), centre));
        add_joints(
            e,
            vec![
                JointSpec::revolute(None, plate, Vec3::Z, [centre, Vec3::ZERO])
                    .motor(SPEED as f32, TORQUE as f32),
            ],
        );
        let steps = self.steps(s, size);
        Box::new(Run {
            plate,
            dt: f64::from(s.dt()),
            steps: 0,
            settle: steps.saturating_sub(steps_for(1.0, s)),
            last: 0.0,
            reached_at: None,
            speed_error_sum: 0.0,
            samples: 0,
        })
    }
}

impl Run {
    fn time_error(&self) -> f64 {
        self.reached_at
            .map_or(f64::INFINITY, |t| (t - exact_time()).abs() / exact_time())
    }
    fn speed_error(&self) -> f64 {
        self.speed_error_sum / self.samples.max(1) as f64
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        self.steps += 1;
        let w = f64::from(e.angular_velocity(self.plate).z);
        let goal = REACHED * SPEED;
        if self.reached_at.is_none() && w >= goal {
            let frac = (goal - self.last) / (w - self.last);
            self.reached_at = Some((self.steps as f64 - 1.0 + frac) * self.dt);
        }
        self.last = w;
        if self.steps > self.settle {
            self.speed_error_sum += (w - SPEED).abs() / SPEED;
            self.samples += 1;
        }
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        let (t, s) = (self.time_error(), self.speed_error());
        if t.is_nan() || s.is_nan() {
            f64::NAN
        } else {
            t.max(s)
        }
    }
    fn detail(&self, _e: &dyn Engine) -> Option<String> {
        Some(format!(
            "99 % of the speed at {} (exact {:.4} s), held speed off by {:.3e} of it",
            self.reached_at
                .map_or("never".to_string(), |t| format!("{t:.4} s")),
            exact_time(),
            self.speed_error()
        ))
    }
}
