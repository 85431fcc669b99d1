//! Frictionless random stacks: 16 stacks of 3–6 boxes of assorted sizes (10–80 cm), each
//! turned about the vertical and off its support's centre, every surface frictionless, for
//! 20 s: placed on each other (`frictionless_random`), or dropped onto each other from 2 cm
//! apart (`frictionless_drops`). Every stack is in equilibrium once landed: the centre of
//! mass of the boxes above each face lies 3 cm or more inside both boxes of that face, and
//! nothing but the contact normals acts sideways. Error: the stacks in which a box moved more
//! than 2 cm sideways, of 16 (of the first 6 in quick mode; ideal: 0).
//!
//! Dropped, the landings rock the boxes, and without friction a rocking face pushes its load
//! sideways for good: real boxes would slide too, a little; both engines let most stacks
//! slide apart.

use onyx_physics::glam::{Quat, Vec2, Vec3};

use super::{steps_for, Scene, Size, Trial};
use crate::engine::{BodyId, BodySpec, Engine, ShapeSpec, StepSettings};

/// Stacks in the scene (the first six of them in quick mode).
const STACKS: usize = 16;
const QUICK_STACKS: usize = 6;
/// How far inside both boxes of each face the load above it stays, m.
const INSIDE: f32 = 0.03;
/// Sideways drift past which a stack counts as slid apart, m.
const SLID: f32 = 0.02;

/// See the module docs.
pub struct FrictionlessStacksRandom {
    /// Gap between a box and the one it falls onto, m.
    pub gap: f32,
}

/// Placed on each other.
pub const PLACED: FrictionlessStacksRandom = FrictionlessStacksRandom { gap: 0.0 };
/// Dropped from 2 cm apart.
pub const DROPPED: FrictionlessStacksRandom = FrictionlessStacksRandom { gap: 0.02 };

/// One box of a stack: half extents, centre (x, z) and turn about the vertical.
#[derive(Clone, Copy)]
struct Slab {
    half: Vec3,
    at: Vec2,
    yaw: f32,
}

impl Slab {
    /// Whether `p` (x, z) is `INSIDE` within this box's footprint.
    fn holds(&self, p: Vec2) -> bool {
        let d = Vec2::from_angle(-self.yaw).rotate(p - self.at);
        d.x.abs() < self.half.x - INSIDE && d.y.abs() < self.half.z - INSIDE
    }
}

/// Deterministic draws (xorshift64*), the same stacks for both engines at every setting.
struct Draw(u64);

impl Draw {
    fn unit(&mut self) -> f32 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 40) as f32 / (1u64 << 24) as f32
    }
    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.unit()
    }
}

/// A stack of 3–6 boxes whose every face holds the load above it (drawn until one does).
fn stack(draw: &mut Draw) -> Vec<Slab> {
    loop {
        let n = 3 + (draw.unit() * 4.0) as usize;
        let mut slabs: Vec<Slab> = Vec::with_capacity(n);
        let mut at = Vec2::ZERO;
        for _ in 0..n {
            let half = Vec3::new(
                draw.range(0.1, 0.4),
                draw.range(0.05, 0.25),
                draw.range(0.1, 0.4),
            );
            if let Some(below) = slabs.last() {
                at += Vec2::new(
                    draw.range(-0.3, 0.3) * half.x.min(below.half.x),
                    draw.range(-0.3, 0.3) * half.z.min(below.half.z),
                );
            }
            let yaw = draw.range(-0.4, 0.4);
            slabs.push(Slab { half, at, yaw });
        }
        let holds = (0..n - 1).all(|i| {
            let above = &slabs[i + 1..];
            let mass: f32 = above.iter().map(|s| s.half.x * s.half.y * s.half.z).sum();
            let com = above
                .iter()
                .map(|s| s.at * (s.half.x * s.half.y * s.half.z))
                .sum::<Vec2>()
                / mass;
            slabs[i].holds(com) && slabs[i + 1].holds(com)
        });
        if holds {
            return slabs;
        }
    }
}

struct Run {
    /// Each stack's boxes and where they started.
    stacks: Vec<Vec<(BodyId, Vec3)>>,
    slid: Vec<bool>,
}

impl Scene for FrictionlessStacksRandom {
    fn name(&self) -> &'static str {
        if self.gap > 0.0 {
            "frictionless_drops"
        } else {
            "frictionless_random"
        }
    }
    fn metric(&self) -> &'static str {
        if self.gap > 0.0 {
            "random frictionless stacks dropped from 2 cm apart that slid apart (a box > 2 cm sideways) within 20 s, of 16 (6 quick)"
        } else {
            "random frictionless stacks placed at rest that slid apart (a box > 2 cm sideways) within 20 s, of 16 (6 quick)"
        }
    }
    fn steps(&self, s: StepSettings, _size: Size) -> usize {
        steps_for(20.0, s)
    }
    fn build(&self, e: &mut dyn Engine, _s: StepSettings, size: Size) -> Box<dyn Trial> {
        e.add(&BodySpec::ground(Vec3::ZERO, 40.0).friction(0.0));
        let mut draw = Draw(0x9E37_79B9_7F4A_7C15);
        let n = match size {
            Size::Quick => QUICK_STACKS,
            Size::Full => STACKS,
        };
        let mut stacks = Vec::with_capacity(n);
        for k in 0..n {
            let origin = Vec2::new(-15.0 + 4.0 * (k % 8) as f32, -2.0 + 4.0 * (k / 8) as f32);
            let mut y = 0.0;
            let mut boxes = Vec::new();
            for slab in stack(&mut draw) {
                y += slab.half.y;
                let at = origin + slab.at;
                let p = Vec3::new(at.x, y, at.y);
                let id = e.add(
                    &BodySpec::dynamic(ShapeSpec::Cuboid(slab.half), p)
                        .rotation(Quat::from_rotation_y(slab.yaw))
                        .friction(0.0),
                );
                boxes.push((id, p));
                y += slab.half.y + self.gap;
            }
            stacks.push(boxes);
        }
        let slid = vec![false; stacks.len()];
        Box::new(Run { stacks, slid })
    }
}

impl Trial for Run {
    fn observe(&mut self, e: &dyn Engine) {
        for (boxes, slid) in self.stacks.iter().zip(&mut self.slid) {
            for &(id, p0) in boxes {
                let p = e.position(id);
                let d = Vec2::new(p.x - p0.x, p.z - p0.z).length();
                if d > SLID || d.is_nan() {
                    *slid = true;
                }
            }
        }
    }
    fn figure(&self, _e: &dyn Engine) -> f64 {
        self.slid.iter().filter(|&&s| s).count() as f64
    }
}
