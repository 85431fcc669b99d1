//! [`Cuboid`] shape (box).

use glam::Vec3;

/// Box centred at the collider origin, aligned with its local axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cuboid {
    /// Half extents in metres (`>= 0` each; zero gives a flat or point box).
    pub half_extents: Vec3,
}

impl Cuboid {
    /// The 8 corners; corner `i` has sign `-` on axis `k` when bit `k` of `i` is clear.
    #[must_use]
    pub fn vertices(&self) -> [Vec3; 8] {
        let h = self.half_extents;
        std::array::from_fn(|i| {
            Vec3::new(
                if i & 1 != 0 { h.x } else { -h.x },
                if i & 2 != 0 { h.y } else { -h.y },
                if i & 4 != 0 { h.z } else { -h.z },
            )
        })
    }

    /// The 12 edges as pairs of corner indices.
    pub const EDGES: [(usize, usize); 12] = [
        (0, 1),
        (2, 3),
        (4, 5),
        (6, 7),
        (0, 2),
        (1, 3),
        (4, 6),
        (5, 7),
        (0, 4),
        (1, 5),
        (2, 6),
        (3, 7),
    ];
}
