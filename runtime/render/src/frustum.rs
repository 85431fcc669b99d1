//! [`Frustum`]: the six planes of a view-projection, for culling bounding spheres.

use glam::{Mat4, Vec3, Vec4};

/// The six inward-facing planes of a view volume (wgpu clip space: depth 0..1), stored as
/// columns (all x components together, …) in two groups of four lanes, so a sphere is tested
/// against every plane with a few vector operations. The two spare lanes hold a plane every
/// point is inside.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frustum {
    /// `[x, y, z, d]` of planes 0–3 (`[0]`) and 4–5 plus the spare lanes (`[1]`); a point p
    /// is inside a plane when `n·p + d >= 0`, with n normalised.
    lanes: [[Vec4; 4]; 2],
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
        let everything = Vec4::new(0.0, 0.0, 0.0, 1.0);
        let group = |p: [Vec4; 4]| {
            [
                Vec4::new(p[0].x, p[1].x, p[2].x, p[3].x),
                Vec4::new(p[0].y, p[1].y, p[2].y, p[3].y),
                Vec4::new(p[0].z, p[1].z, p[2].z, p[3].z),
                Vec4::new(p[0].w, p[1].w, p[2].w, p[3].w),
            ]
        };
        Self {
            lanes: [
                group([planes[0], planes[1], planes[2], planes[3]]),
                group([planes[4], planes[5], everything, everything]),
            ],
        }
    }

    /// Whether a sphere (world space) is at least partly inside.
    #[must_use]
    pub fn intersects_sphere(&self, center: Vec3, radius: f32) -> bool {
        let (x, y, z) = (
            Vec4::splat(center.x),
            Vec4::splat(center.y),
            Vec4::splat(center.z),
        );
        let limit = Vec4::splat(-radius);
        self.lanes.iter().all(|[px, py, pz, pd]| {
            let distance = *px * x + *py * y + *pz * z + *pd;
            distance.cmpge(limit).all()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spheres_are_inside_outside_or_touching() {
        // Looking down −Z from the origin (the view is the identity).
        let view_proj = glam::camera::rh::proj::directx::perspective(1.0, 1.0, 0.1, 100.0);
        let frustum = Frustum::from_view_projection(&view_proj);
        assert!(frustum.intersects_sphere(Vec3::new(0.0, 0.0, -10.0), 0.5));
        assert!(
            !frustum.intersects_sphere(Vec3::new(0.0, 0.0, 10.0), 0.5),
            "behind"
        );
        assert!(
            !frustum.intersects_sphere(Vec3::new(0.0, 0.0, -200.0), 0.5),
            "past far"
        );
        assert!(
            !frustum.intersects_sphere(Vec3::new(50.0, 0.0, -10.0), 1.0),
            "to the side"
        );
        // Centre outside the right plane, but the sphere reaches in.
        assert!(frustum.intersects_sphere(Vec3::new(6.0, 0.0, -10.0), 2.0));
    }
}
