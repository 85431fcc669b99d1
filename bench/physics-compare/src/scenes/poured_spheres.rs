//! Poured spheres: 8,000 spheres (r = 0.1 m; 300 quick) released in a 16 × 16 column grid
//! above an open 4 × 4 m box (ground + four 12 m walls), settled for 3 s (1.5 s quick).
//! Error: share of spheres outside the box at the end + the largest penetration (sphere into
//! wall/floor or sphere into sphere) at the end, m.

use onyx_physics::glam::Vec3;

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

const R: f32 = 0.1;
/// Interior half width of the box.
const W: f32 = 2.0;
/// Wall half height.
const WH: f32 = 6.0;
const GRID: usize = 16;

/// See the module docs.
pub struct PouredSpheres;

struct Run {
    spheres: Vec<BodyId>,
}

impl Scene for PouredSpheres {
    fn name(&self) -> &'static str {
        "poured_spheres"
    }
    fn metric(&self) -> &'static str {
        "share of spheres escaped + max penetration (m), 8000 spheres in a box"
    }
    fn steps(&self, s: StepSettings, size: Size) -> usize {
        match size {
            Size::Quick => steps_for(1.5, s),
            Size::Full => steps_for(3.0, s),
        }
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, size: Size) -> Box<dyn Trial> {
        let n = match size {
            Size::Quick => 300,
            Size::Full => 8_000,
        };
        e.add(&BodySpec::ground(Vec3::ZERO, W + 1.0));
        let t = 0.25;
        for sign in [-1.0f32, 1.0] {
            e.add(&BodySpec::fixed(
                ShapeSpec::Cuboid(Vec3::new(t, WH, W + 2.0 * t)),
                Vec3::new(sign * (W + t), WH, 0.0),
            ));
            e.add(&BodySpec::fixed(
                ShapeSpec::Cuboid(Vec3::new(W, WH, t)),
                Vec3::new(0.0, WH, sign * (W + t)),
            ));
        }
        let spacing = 2.0 * (W - R) / (GRID - 1) as f32;
        let spheres = (0..n)
            .map(|k| {
                let layer = k / (GRID * GRID);
                let i = (k / GRID) % GRID;
                let j = k % GRID;
                // Odd layers shifted by a quarter spacing so columns do not stack exactly.
                let shift = if layer % 2 == 1 { 0.25 * spacing } else { 0.0 };
                let p = Vec3::new(
                    -(W - R) + i as f32 * spacing + shift.min(W - R),
                    0.5 + R + layer as f32 * 2.2 * R,
                    -(W - R) + j as f32 * spacing,
                );
                let p = p.clamp(Vec3::new(-(W - R), 0.0, -(W - R)), Vec3::splat(1e3));
                e.add(&BodySpec::dynamic(ShapeSpec::Sphere(R), p))
            })
            .collect();
        Box::new(Run { spheres })
    }
}

impl Trial for Run {
    fn figure(&self, e: &dyn Engine) -> f64 {
        let ps: Vec<Vec3> = self.spheres.iter().map(|&id| e.position(id)).collect();
        if ps.iter().any(|p| !p.is_finite()) {
            return f64::NAN;
        }
        let mut escaped = 0usize;
        let mut pen = 0.0f32;
        for p in &ps {
            let inside = p.x.abs() < W && p.z.abs() < W && p.y > 0.0 && p.y < 2.0 * WH;
            if !inside {
                escaped += 1;
                continue;
            }
            // Floor and walls.
            pen = pen.max(R - p.y);
            pen = pen.max(R - (W - p.x.abs()));
            pen = pen.max(R - (W - p.z.abs()));
        }
        // Sphere pairs: sort by x and sweep.
        let mut sorted = ps.clone();
        sorted.sort_by(|a, b| a.x.total_cmp(&b.x));
        for (i, a) in sorted.iter().enumerate() {
            for b in &sorted[i + 1..] {
                if b.x - a.x >= 2.0 * R {
                    break;
                }
                pen = pen.max(2.0 * R - (*a - *b).length());
            }
        }
        escaped as f64 / ps.len() as f64 + f64::from(pen.max(0.0))
    }
}
