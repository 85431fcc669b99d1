//! Sphere–box analytic contact.

use glam::Vec3;

use super::raw_manifold::RawManifold;
use crate::pose::Pose;

/// Contact between a box (half extents `h` at `pb`, shape A) and a sphere (centre `c`,
/// radius `r`, shape B). Normal from box to sphere.
#[must_use]
pub(crate) fn box_sphere(h: Vec3, pb: &Pose, c: Vec3, r: f32, margin: f32) -> Option<RawManifold> {
    let cl = pb.inverse_transform_point(c);
    let q = cl.clamp(-h, h);
    let diff = cl - q;
    let d2 = diff.length_squared();
    let (n_local, q_local, sep) = if d2 > 1e-12 {
        let d = d2.sqrt();
        if d - r > margin {
            return None;
        }
        (diff / d, q, d - r)
    } else {
        // Centre inside: push out through the nearest face.
        let gap = h - cl.abs();
        let k = if gap.x <= gap.y && gap.x <= gap.z {
            0
        } else if gap.y <= gap.z {
            1
        } else {
            2
        };
        let s = if cl[k] >= 0.0 { 1.0 } else { -1.0 };
        let mut n = Vec3::ZERO;
        n[k] = s;
        let mut qq = cl;
        qq[k] = s * h[k];
        (n, qq, -gap[k] - r)
    };
    let n = pb.rotation * n_local;
    let on_box = pb.transform_point(q_local);
    let on_sphere = c - n * r;
    Some(RawManifold::single(n, (on_box + on_sphere) * 0.5, sep, 0))
}
