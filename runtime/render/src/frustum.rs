//! [`Frustum`]: the six planes of a view-projection, for culling bounding spheres.

use glam::{Mat4, Vec3, Vec4};

/// The six inward-facing planes of a view volume (wgpu clip space: depth 0..1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frustum {
    /// Planes as (normal, d), normalised; a point p is inside when `n·p + d >= 0`.
    planes: [Vec4; 6],
}

impl Frustum {
    /// Extracts the planes from a view-projection matrix (Gribb–Hartmann, 0..1 depth).
    #[must_use]
    pub fn from_view_projection(view_proj: &Mat4) -> Self {
        let r0 = view_proj.row(0);
        let r1 = view_proj.row(1);
        let r2 = view_proj.row(2);
        let r3 = view_proj.row(3);
        let raw = [r3 + r0, r3 - r0, r3 + r1, r3 - r1, r2, r3 - r2];
        let planes = raw.map(|p| {
            let len = p.truncate().length();
            if len > 0.0 {
                p / len
            } else {
                p
            }
        });
        Self { planes }
    }

    /// Whether a sphere (world space) is at least partly inside.
    #[must_use]
    pub fn intersects_sphere(&self, center: Vec3, radius: f32) -> bool {
        self.planes
            .iter()
            .all(|p| p.truncate().dot(center) + p.w >= -radius)
    }
}
