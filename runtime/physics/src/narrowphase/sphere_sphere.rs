//! Sphere–sphere (and point-core) contact.

use glam::Vec3;

use super::raw_manifold::RawManifold;

/// Contact between spheres at `ca`, `cb` with radii `ra`, `rb`; `None` beyond `margin`.
#[must_use]
pub(crate) fn sphere_sphere(
    ca: Vec3,
    ra: f32,
    cb: Vec3,
    rb: f32,
    margin: f32,
) -> Option<RawManifold> {
    let d = cb - ca;
    let dist = d.length();
    let sep = dist - ra - rb;
    if sep > margin {
        return None;
    }
    let n = if dist > 1e-9 { d / dist } else { Vec3::Y };
    let pa = ca + n * ra;
    let pb = cb - n * rb;
    Some(RawManifold::single(n, (pa + pb) * 0.5, sep, 0))
}
