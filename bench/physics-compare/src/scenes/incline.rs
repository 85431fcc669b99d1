//! Incline friction ladder: 1 m boxes resting on fixed 1-per-angle inclines at 20°, 26°, 36°
//! and 45°, μ = 0.6 on both (both engines use one coefficient, so μ_s = μ_d = 0.6 and the
//! stick/slide threshold is atan 0.6 ≈ 31°). Over 1 s, a box counts as sliding when it moved
//! more than 5 cm down the slope. Error: wrong stick/slide decisions + the mean relative
//! error of the sliding boxes' acceleration (2 d / t²) against g (sin θ − μ_d cos θ).

use onyx_physics::glam::{Quat, Vec3};

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const MU: f32 = 0.6;
const G: f32 = 9.81;
const ANGLES_DEG: [f32; 4] = [20.0, 26.0, 36.0, 45.0];
const T: f32 = 1.0;
const SLIDE_THRESHOLD: f32 = 0.05;
/// Half extents of an incline slab.
pub const SLAB: Vec3 = Vec3::new(10.0, 0.5, 2.0);

/// See the module docs.
pub struct Incline;

/// Adds a fixed incline slab at `origin` tilted by `theta` (downhill towards −x), friction
/// `mu`; returns its rotation. A point `local` above the slab's top face maps to
/// `origin + q * (local + SLAB.y · Y)`.
pub fn add_incline(e: &mut dyn Engine, origin: Vec3, theta: f32, mu: f32) -> Quat {
    let q = Quat::from_rotation_z(theta);
    e.add(
        &BodySpec::fixed(ShapeSpec::Cuboid(SLAB), origin)
            .rotation(q)
            .friction(mu),
    );
    q
}

/// Position on the slab at `origin`/`q`: `u` along the slab's local x, `h` above its top face.
#[must_use]
pub fn on_incline(origin: Vec3, q: Quat, u: f32, h: f32) -> Vec3 {
    origin + q * Vec3::new(u, SLAB.y + h, 0.0)
}

struct Block {
    id: BodyId,
    theta: f32,
    start: Vec3,
    down: Vec3,
}

struct Run {
    blocks: Vec<Block>,
}

impl Scene for Incline {
    fn name(&self) -> &'static str {
        "incline"
    }
    fn metric(&self) -> &'static str {
        "wrong stick/slide decisions + mean rel. error of slide accel vs g(sin - mu cos)"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(T, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        let blocks = ANGLES_DEG
            .iter()
            .enumerate()
            .map(|(i, &deg)| {
                let theta = deg.to_radians();
                let origin = Vec3::new(0.0, 0.0, i as f32 * 6.0);
                let q = add_incline(e, origin, theta, MU);
                let start = on_incline(origin, q, 5.0, 0.5);
                let id = e.add(
                    &BodySpec::dynamic(ShapeSpec::Cuboid(Vec3::splat(0.5)), start)
                        .rotation(q)
                        .friction(MU),
                );
                Block {
                    id,
                    theta,
                    start,
                    down: q * Vec3::NEG_X,
                }
            })
            .collect();
        Box::new(Run { blocks })
    }
}

impl Trial for Run {
    fn figure(&self, e: &dyn Engine) -> f64 {
        let mut wrong = 0.0f64;
        let mut rel = 0.0f64;
        let mut sliders = 0usize;
        for b in &self.blocks {
            let p = e.position(b.id);
            if !p.is_finite() {
                return f64::NAN;
            }
            let d = (p - b.start).dot(b.down);
            let expected = G * (b.theta.sin() - MU * b.theta.cos());
            let should_slide = expected > 0.0;
            let slid = d > SLIDE_THRESHOLD;
            if slid != should_slide {
                wrong += 1.0;
            }
            if should_slide {
                let a = 2.0 * d / (T * T);
                rel += f64::from(((a - expected) / expected).abs());
                sliders += 1;
            }
        }
        wrong + rel / sliders.max(1) as f64
    }
}
