//! Long run: 10,000 steps (1,000 quick) of four spheres bouncing with e = 0.5, 0.8, 0.95 and
//! 1.0 (dropped from 1 to 2.5 m) and a 3-box stack resting on a ground, all frictionless so
//! no spin is injected. Total energy (kinetic, rotational, potential above the ground) must
//! never exceed its start: error = max over steps of (E(t) − E₀) / E₀, clamped at 0.

use onyx_physics::glam::Vec3;

use super::{Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const G: f32 = 9.81;
const R: f32 = 0.25;
const H: f32 = 0.5;

/// See the module docs.
pub struct LongRun;

struct Run {
    /// (id, moment of inertia about any axis through the centre per unit mass).
    bodies: Vec<(BodyId, f32)>,
    e0: f64,
    worst: f64,
}

fn energy(e: &dyn Engine, bodies: &[(BodyId, f32)]) -> f64 {
    let mut sum = 0.0f64;
    for &(id, i_per_m) in bodies {
        let m = f64::from(e.mass(id));
        let p = e.position(id);
        let v = e.velocity(id);
        let w = e.angular_velocity(id);
        let ke = 0.5 * f64::from(v.length_squared());
        let re = 0.5 * f64::from(i_per_m * w.length_squared());
        sum += m * (f64::from(G * p.y) + ke + re);
    }
    sum
}

impl Scene for LongRun {
    fn name(&self) -> &'static str {
        "long_run"
    }
    fn metric(&self) -> &'static str {
        "max relative energy growth above the start over the run"
    }
    fn steps(&self, _s: StepSettings, size: Size) -> usize {
        match size {
            Size::Quick => 1_000,
            Size::Full => 10_000,
        }
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        e.add(&BodySpec::ground(Vec3::ZERO, 10.0).friction(0.0));
        let mut bodies = Vec::new();
        for (i, &rest) in [0.5f32, 0.8, 0.95, 1.0].iter().enumerate() {
            let p = Vec3::new(-3.0 + 1.5 * i as f32, R + 1.0 + 0.5 * i as f32, 0.0);
            let id = e.add(
                &BodySpec::dynamic(ShapeSpec::Sphere(R), p)
                    .friction(0.0)
                    .restitution(rest),
            );
            bodies.push((id, 0.4 * R * R));
        }
        for k in 0..3 {
            let p = Vec3::new(3.0, H + 2.0 * H * k as f32, 0.0);
            let id = e.add(&BodySpec::dynamic(ShapeSpec::Cuboid(Vec3::splat(H)), p).friction(0.0));
            bodies.push((id, (2.0 * H) * (2.0 * H) / 6.0));
        }
        let e0 = energy(e, &bodies);
        Box::new(Run {
            bodies,
            e0,
            worst: 0.0,
        })
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        let now = energy(e, &self.bodies);
        let growth = if now.is_finite() {
            (now - self.e0) / self.e0
        } else {
            f64::NAN
        };
        // NaN sticks (f64::max would drop it).
        if growth.is_nan() || self.worst.is_nan() {
            self.worst = f64::NAN;
        } else {
            self.worst = self.worst.max(growth);
        }
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        self.worst
    }
}
