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
    let (n, point, sep) = ball_contact(ca, ra, cb, rb, margin)?;
    Some(RawManifold::single(n, point, sep, 0))
}

/// The geometry of [`sphere_sphere`] without a manifold: unit normal from A to B, the point
/// midway between the surfaces and the signed separation; `None` beyond `margin`.
#[must_use]
#[inline]
pub(crate) fn ball_contact(
    ca: Vec3,
    ra: f32,
    cb: Vec3,
    rb: f32,
    margin: f32,
) -> Option<(Vec3, Vec3, f32)> {
    let d = cb - ca;
    let dist = d.length();
    let sep = dist - ra - rb;
    if sep > margin {
        return None;
    }
    let n = if dist > 1e-9 { d / dist } else { Vec3::Y };
    let pa = ca + n * ra;
    let pb = cb - n * rb;
    Some((n, (pa + pb) * 0.5, sep))
}
