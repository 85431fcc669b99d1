//! Capsule–sphere and capsule–capsule analytic contacts (segment closest points).

use glam::Vec3;

use super::raw_manifold::{RawManifold, RawPoint};
use super::sphere_sphere::sphere_sphere;

/// Cosine above which two capsule axes count as parallel (two-point manifold).
pub const CAPSULE_PARALLEL_COS: f32 = 0.995;

/// Closest point to `p` on segment `ab`.
#[must_use]
pub(crate) fn closest_on_segment(p: Vec3, a: Vec3, b: Vec3) -> Vec3 {
    let ab = b - a;
    let den = ab.length_squared();
    if den <= 1e-20 {
        return a;
    }
    a + ab * ((p - a).dot(ab) / den).clamp(0.0, 1.0)
}

/// Closest points `(on ab, on cd)` between two segments (Ericson §5.1.9).
#[must_use]
pub(crate) fn closest_segment_segment(a: Vec3, b: Vec3, c: Vec3, d: Vec3) -> (Vec3, Vec3) {
    let d1 = b - a;
    let d2 = d - c;
    let r = a - c;
    let aa = d1.length_squared();
    let ee = d2.length_squared();
    let f = d2.dot(r);
    const EPS: f32 = 1e-12;
    let (s, t);
    if aa <= EPS && ee <= EPS {
        return (a, c);
    }
    if aa <= EPS {
        s = 0.0;
        t = (f / ee).clamp(0.0, 1.0);
    } else {
        let cc = d1.dot(r);
        if ee <= EPS {
            t = 0.0;
            s = (-cc / aa).clamp(0.0, 1.0);
        } else {
            let bb = d1.dot(d2);
            let den = aa * ee - bb * bb;
            let mut s0 = if den > EPS * aa * ee {
                ((bb * f - cc * ee) / den).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let mut t0 = (bb * s0 + f) / ee;
            if t0 < 0.0 {
                t0 = 0.0;
                s0 = (-cc / aa).clamp(0.0, 1.0);
            } else if t0 > 1.0 {
                t0 = 1.0;
                s0 = ((bb - cc) / aa).clamp(0.0, 1.0);
            }
            s = s0;
            t = t0;
        }
    }
    (a + d1 * s, c + d2 * t)
}

/// Capsule (segment `a0 a1`, radius `ra`, shape A) against a sphere (shape B).
#[must_use]
pub(crate) fn capsule_sphere(
    a0: Vec3,
    a1: Vec3,
    ra: f32,
    c: Vec3,
    rb: f32,
    margin: f32,
) -> Option<RawManifold> {
    let p = closest_on_segment(c, a0, a1);
    sphere_sphere(p, ra, c, rb, margin)
}

/// Capsule A (segment `a0 a1`, radius `ra`) against capsule B (`b0 b1`, `rb`).
#[must_use]
pub(crate) fn capsule_capsule(
    a0: Vec3,
    a1: Vec3,
    ra: f32,
    b0: Vec3,
    b1: Vec3,
    rb: f32,
    margin: f32,
) -> Option<RawManifold> {
    let da = a1 - a0;
    let db = b1 - b0;
    let la = da.length();
    let lb = db.length();
    if la > 1e-6 && lb > 1e-6 && (da.dot(db) / (la * lb)).abs() > CAPSULE_PARALLEL_COS {
        // Parallel: project B's ends on A and clip to the overlap.
        let axis = da / la;
        let t0 = (b0 - a0).dot(axis);
        let t1 = (b1 - a0).dot(axis);
        let lo = t0.min(t1).max(0.0);
        let hi = t0.max(t1).min(la);
        if hi - lo > 1e-4 {
            let mut m: Option<RawManifold> = None;
            for (k, t) in [lo, hi].into_iter().enumerate() {
                let pa = a0 + axis * t;
                let pb = closest_on_segment(pa, b0, b1);
                let d = pb - pa;
                let dist = d.length();
                let sep = dist - ra - rb;
                if sep > margin {
                    continue;
                }
                let n = if dist > 1e-9 {
                    d / dist
                } else {
                    axis.any_orthonormal_vector()
                };
                let mm = m.get_or_insert_with(|| RawManifold::new(n));
                let p = (pa + n * ra + pb - n * rb) * 0.5;
                mm.points.push(RawPoint {
                    point: p,
                    separation: sep,
                    id: k as u32,
                });
            }
            return m;
        }
    }
    let (pa, pb) = closest_segment_segment(a0, a1, b0, b1);
    sphere_sphere(pa, ra, pb, rb, margin)
}
