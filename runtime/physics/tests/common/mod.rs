//! Shared helpers for the physics tests.
#![allow(dead_code)]

use onyx_physics::glam::Vec3;
use onyx_physics::{BodyHandle, ColliderDesc, PhysicsSettings, PhysicsWorld, RigidBodyDesc};

/// Standard gravity used by the tests, m/s².
pub const G: f32 = 9.81;

/// World with default settings and a ground half space at y = 0 with the given friction.
pub fn world_with_ground(friction: f32) -> (PhysicsWorld, BodyHandle) {
    let mut w = PhysicsWorld::new(PhysicsSettings::default());
    let g = w.insert_body(RigidBodyDesc::fixed());
    w.insert_collider(ColliderDesc::half_space(Vec3::Y).friction(friction), g);
    (w, g)
}

/// The eight corners of a cube of half size `half` centred at the origin (for hull cubes).
pub fn cube_corners(half: f32) -> Vec<Vec3> {
    (0..8)
        .map(|i| {
            Vec3::new(
                if i & 1 == 0 { -half } else { half },
                if i & 2 == 0 { -half } else { half },
                if i & 4 == 0 { -half } else { half },
            )
        })
        .collect()
}

/// Steps `n` times.
pub fn run(w: &mut PhysicsWorld, n: usize) {
    for _ in 0..n {
        w.step();
    }
}

/// Deterministic pseudo-random numbers (splitmix64) for seeded tests.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        let u = (self.next_u64() >> 40) as f32 / (1u64 << 24) as f32;
        lo + (hi - lo) * u
    }
    pub fn vec3(&mut self, lo: f32, hi: f32) -> Vec3 {
        Vec3::new(self.range(lo, hi), self.range(lo, hi), self.range(lo, hi))
    }
    pub fn quat(&mut self) -> onyx_physics::glam::Quat {
        let v = onyx_physics::glam::Vec4::new(
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
        );
        let v = if v.length_squared() < 1e-4 {
            onyx_physics::glam::Vec4::W
        } else {
            v.normalize()
        };
        onyx_physics::glam::Quat::from_vec4(v)
    }
}
