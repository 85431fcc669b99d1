//! Reference/incident feature clipping (Sutherland–Hodgman) that turns a contact normal
//! into a multi-point manifold.

use glam::Vec3;

use super::raw_manifold::{RawManifold, RawPoint, MAX_CANDIDATE_POINTS};

/// Clips the `incident` feature (polygon, segment or point) against the side planes of the
/// `reference` polygon (counter-clockwise around `ref_normal`, the outward normal of the
/// reference shape) and appends points whose separation is at most `margin`.
///
/// Radii are the rounding of each core (capsules, spheres). The manifold normal is
/// `ref_normal` when the reference belongs to shape A, else `-ref_normal`. Returns the number
/// of points added.
#[allow(clippy::too_many_arguments)]
pub(crate) fn clip_features(
    reference: &[Vec3],
    ref_normal: Vec3,
    ref_radius: f32,
    incident: &[Vec3],
    inc_radius: f32,
    margin: f32,
    id_base: u32,
    out: &mut RawManifold,
) -> usize {
    let mut buf_a: [(Vec3, u32); MAX_CANDIDATE_POINTS] = [(Vec3::ZERO, 0); MAX_CANDIDATE_POINTS];
    let mut buf_b: [(Vec3, u32); MAX_CANDIDATE_POINTS] = [(Vec3::ZERO, 0); MAX_CANDIDATE_POINTS];
    let mut n_in = incident.len().min(MAX_CANDIDATE_POINTS);
    for (i, p) in incident.iter().take(n_in).enumerate() {
        buf_a[i] = (*p, i as u32);
    }
    let closed = n_in >= 3;
    let nr = reference.len();
    for k in 0..nr {
        let r0 = reference[k];
        let r1 = reference[(k + 1) % nr];
        let side = (r1 - r0).cross(ref_normal);
        let len = side.length();
        if len <= 1e-12 {
            continue;
        }
        let side = side / len;
        let off = side.dot(r0);
        let mut n_out = 0;
        if n_in == 1 {
            if side.dot(buf_a[0].0) - off <= 0.0 {
                buf_b[0] = buf_a[0];
                n_out = 1;
            }
        } else if !closed {
            let (p, pid) = buf_a[0];
            let (q, qid) = buf_a[1];
            let dp = side.dot(p) - off;
            let dq = side.dot(q) - off;
            if dp <= 0.0 || dq <= 0.0 {
                let cut = |t: f32| p + (q - p) * t;
                let cid = 0x100 | ((k as u32) << 4);
                buf_b[0] = if dp <= 0.0 {
                    (p, pid)
                } else {
                    (cut(dp / (dp - dq)), cid)
                };
                buf_b[1] = if dq <= 0.0 {
                    (q, qid)
                } else {
                    (cut(dp / (dp - dq)), cid | 1)
                };
                n_out = 2;
            }
        } else {
            for e in 0..n_in {
                let (p, pid) = buf_a[e];
                let (q, _) = buf_a[(e + 1) % n_in];
                let dp = side.dot(p) - off;
                let dq = side.dot(q) - off;
                if dp <= 0.0 && n_out < MAX_CANDIDATE_POINTS {
                    buf_b[n_out] = (p, pid);
                    n_out += 1;
                }
                if (dp < 0.0) != (dq < 0.0) && n_out < MAX_CANDIDATE_POINTS {
                    let t = dp / (dp - dq);
                    buf_b[n_out] = (p + (q - p) * t, 0x100 | ((k as u32) << 4) | (pid & 0xF));
                    n_out += 1;
                }
            }
        }
        buf_a[..n_out].copy_from_slice(&buf_b[..n_out]);
        n_in = n_out;
        if n_in == 0 {
            return 0;
        }
    }
    let r0 = reference[0];
    let before = out.points.len();
    for &(q, id) in &buf_a[..n_in] {
        let d = ref_normal.dot(q - r0);
        let sep = d - ref_radius - inc_radius;
        if sep <= margin {
            let ref_surface = q - ref_normal * (d - ref_radius);
            let inc_surface = q - ref_normal * inc_radius;
            out.points.push(RawPoint {
                point: (ref_surface + inc_surface) * 0.5,
                separation: sep,
                id: id_base | id,
            });
        }
    }
    out.points.len() - before
}
