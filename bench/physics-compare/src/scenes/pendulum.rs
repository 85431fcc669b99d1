//! Pendulums on a hinge to the world: a 5 cm sphere 1 m below its pivot, let go from rest at
//! 5° and at 120°, swinging for 10 s (6 s quick). Error: the larger relative error of the
//! measured period (mean over the upward zero crossings of the angle) against the exact
//! period of that amplitude, `T = 4 √(L/g) K(sin(θ₀/2))` with `K` the complete elliptic
//! integral of the first kind (by the arithmetic-geometric mean) and `L = I/(m d)` the
//! sphere's equivalent length (its own inertia included). The detail also gives how much of
//! its amplitude each kept (energy lost or gained shows there).

use std::f64::consts::PI;

use onyx_physics::glam::Vec3;

use super::{add_joints, max_or_nan, steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};
use crate::joint_spec::JointSpec;

const ARM: f32 = 1.0;
const RADIUS: f32 = 0.05;
const G: f64 = 9.81;
const AMPLITUDES_DEG: [f32; 2] = [5.0, 120.0];

/// See the module docs.
pub struct Pendulum;

/// The complete elliptic integral of the first kind, `K(k) = π / (2 agm(1, √(1 − k²)))`.
#[must_use]
pub fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    for _ in 0..32 {
        let (an, bn) = (0.5 * (a + b), (a * b).sqrt());
        (a, b) = (an, bn);
        if (a - b).abs() < 1e-15 * a {
            break;
        }
    }
    PI / (2.0 * a)
}

/// The exact period of a rigid pendulum of equivalent length `l` let go from `amplitude`
/// (rad) at rest.
#[must_use]
pub fn exact_period(l: f64, amplitude: f64) -> f64 {
    4.0 * (l / G).sqrt() * elliptic_k((0.5 * amplitude).sin())
}

/// One pendulum as it is observed.
struct Swing {
    bob: BodyId,
    pivot: Vec3,
    amplitude: f32,
    /// Angle at the last step (from straight down, about +Z).
    last: f64,
    /// Times of the upward zero crossings, s.
    crossings: Vec<f64>,
    /// Largest |angle| since the last crossing but one, i.e. over the latest full swing.
    peak: f64,
    peak_now: f64,
}

struct Run {
    swings: Vec<Swing>,
    dt: f64,
    steps: usize,
}

impl Scene for Pendulum {
    fn name(&self) -> &'static str {
        "pendulum"
    }
    fn metric(&self) -> &'static str {
        "larger relative period error of a 5° and a 120° hinge pendulum vs the exact \
         (elliptic-integral) period, fraction"
    }
    fn steps(&self, s: StepSettings, size: Size) -> usize {
        match size {
            Size::Quick => steps_for(6.0, s),
            Size::Full => steps_for(10.0, s),
        }
    }
    fn build(&self, e: &mut dyn Engine, s: StepSettings, _size: Size) -> Box<dyn Trial> {
        let mut joints = Vec::new();
        let mut swings = Vec::new();
        for (i, &deg) in AMPLITUDES_DEG.iter().enumerate() {
            let a = deg.to_radians();
            let pivot = Vec3::new(3.0 * i as f32, 3.0, 0.0);
            let offset = ARM * Vec3::new(a.sin(), -a.cos(), 0.0);
            let bob = e.add(&BodySpec::dynamic(
                ShapeSpec::Sphere(RADIUS),
                pivot + offset,
            ));
            joints.push(JointSpec::revolute(None, bob, Vec3::Z, [pivot, -offset]));
            swings.push(Swing {
                bob,
                pivot,
                amplitude: a,
                last: f64::from(a),
                crossings: Vec::new(),
                peak: 0.0,
                peak_now: 0.0,
            });
        }
        add_joints(e, joints);
        Box::new(Run {
            swings,
            dt: f64::from(s.dt()),
            steps: 0,
        })
    }
}

impl Swing {
    fn observe(&mut self, e: &dyn Engine, t: f64, dt: f64) {
        let d = e.position(self.bob) - self.pivot;
        let angle = f64::from(d.x).atan2(f64::from(-d.y));
        if self.last < 0.0 && angle >= 0.0 {
            let frac = -self.last / (angle - self.last);
            self.crossings.push(t - dt + frac * dt);
            self.peak = self.peak_now;
            self.peak_now = 0.0;
        }
        self.peak_now = self.peak_now.max(angle.abs());
        self.last = angle;
    }

    /// Measured period, s (NaN with fewer than two crossings or a body gone).
    fn period(&self) -> f64 {
        match (self.crossings.first(), self.crossings.last()) {
            (Some(a), Some(b)) if self.crossings.len() >= 2 => {
                (b - a) / (self.crossings.len() - 1) as f64
            }
            _ => f64::NAN,
        }
    }

    fn exact(&self) -> f64 {
        let (d, r) = (f64::from(ARM), f64::from(RADIUS));
        exact_period(d + 0.4 * r * r / d, f64::from(self.amplitude))
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        self.steps += 1;
        let t = self.steps as f64 * self.dt;
        for s in &mut self.swings {
            s.observe(e, t, self.dt);
        }
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        max_or_nan(
            self.swings
                .iter()
                .map(|s| (s.period() - s.exact()).abs() / s.exact()),
        )
    }
    fn detail(&self, _e: &dyn Engine) -> Option<String> {
        let parts: Vec<String> = self
            .swings
            .iter()
            .map(|s| {
                format!(
                    "{:.0}°: period {:.4} s (exact {:.4} s, {:+.3} %), last swing {:.1} % of \
                     the amplitude",
                    s.amplitude.to_degrees(),
                    s.period(),
                    s.exact(),
                    100.0 * (s.period() / s.exact() - 1.0),
                    100.0 * s.peak / f64::from(s.amplitude)
                )
            })
            .collect();
        Some(parts.join("; "))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_period_matches_small_angle_and_known_large_amplitude_values() {
        let small = 2.0 * PI * (1.0 / G).sqrt();
        assert!((exact_period(1.0, 1e-4) / small - 1.0).abs() < 1e-8);
        // T(90°)/T₀ = 1.18034 and T(120°)/T₀ = 1.37288 (tabulated).
        assert!((exact_period(1.0, PI / 2.0) / small - 1.180_34).abs() < 1e-5);
        assert!((exact_period(1.0, 2.0 * PI / 3.0) / small - 1.372_88).abs() < 1e-5);
    }
}
