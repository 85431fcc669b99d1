//! Wide-wall CCD: bullets (5 cm spheres and boxes, CCD on, no gravity, spinning) fired at
//! 300 and 1,000 m/s at static walls 1 cm thick and 1 m, 200 m and 10 km wide, spread over
//! each wall's face. Error: share of bullets whose centre crossed a wall inside its face
//! (ideal: 0).

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const WALL_HALF: f32 = 0.005;
/// Half widths of the walls, metres.
const WIDTHS: [f32; 3] = [0.5, 100.0, 5_000.0];

/// See the module docs.
pub struct WideWallCcd;

struct Run {
    /// (bullet, wall centre z, wall half width, last position, crossed).
    bullets: Vec<(BodyId, f32, f32, Vec3, bool)>,
}

impl Scene for WideWallCcd {
    fn name(&self) -> &'static str {
        "wide_wall_ccd"
    }
    fn metric(&self) -> &'static str {
        "share of CCD bullets (300/1000 m/s) through 1 cm walls 1 m-10 km wide"
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(0.25, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, _size: Size) -> Box<dyn Trial> {
        let mut bullets = Vec::new();
        // Walls side by side along z, far enough apart not to meet.
        let mut z = 0.0f32;
        for (w, &half) in WIDTHS.iter().enumerate() {
            let wall_z = z + half;
            z += 2.0 * half + 10.0;
            e.add(&BodySpec::fixed(
                ShapeSpec::Cuboid(Vec3::new(WALL_HALF, half, half)),
                Vec3::new(0.0, 0.0, wall_z),
            ));
            for (k, f) in [-0.9f32, 0.0, 0.6].into_iter().enumerate() {
                for (j, speed) in [300.0f32, 1_000.0].into_iter().enumerate() {
                    let shape = if (k + j + w) % 2 == 0 {
                        ShapeSpec::Sphere(0.05)
                    } else {
                        ShapeSpec::Cuboid(Vec3::new(0.05, 0.03, 0.04))
                    };
                    let p = Vec3::new(-5.0, f * half, wall_z + 0.5 * f * half);
                    let id = e.add(
                        &BodySpec::dynamic(shape, p)
                            .velocity(Vec3::new(speed, 0.0, 0.0))
                            .angular_velocity(Vec3::new(7.0, -11.0, 13.0))
                            .gravity_scale(0.0)
                            .density(7800.0)
                            .ccd(true),
                    );
                    bullets.push((id, wall_z, half, p, false));
                }
            }
        }
        Box::new(Run { bullets })
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        for b in &mut self.bullets {
            let p = e.position(b.0);
            let p0 = b.3;
            if !p.is_finite() {
                b.4 = true;
            } else if p0.x < 0.0 && p.x >= 0.0 {
                let at = p0 + (p - p0) * (-p0.x / (p.x - p0.x));
                if at.y.abs() <= b.2 && (at.z - b.1).abs() <= b.2 {
                    b.4 = true;
                }
            }
            b.3 = p;
        }
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        let through = self.bullets.iter().filter(|b| b.4).count();
        through as f64 / self.bullets.len() as f64
    }
}
