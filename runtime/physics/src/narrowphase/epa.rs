//! EPA: penetration depth, normal and witness points of overlapping convex cores
//! ([`epa_penetration`]), seeded by the GJK simplex.

use glam::Vec3;

use super::gjk::{closest_on_triangle, support, Simplex, SupportPoint};
use crate::pose::Pose;
use crate::shape::ConvexCore;

/// Iteration cap of EPA (one polytope vertex added per iteration). Bounded `[8, 128]`;
/// hitting it reports [`EpaStatus::NotConverged`] with the best face found.
pub const EPA_MAX_ITERATIONS: u32 = 48;

/// Face cap of the expanding polytope. Bounded `[32, 512]`.
pub const EPA_MAX_FACES: usize = 192;

/// Convergence tolerance: stop when the support point along the closest face normal is at
/// most `EPA_TOLERANCE · max(1, depth)` metres beyond that face. Bounded `[1e-6, 1e-3]`.
pub const EPA_TOLERANCE: f32 = 1e-4;

/// Outcome of [`epa_penetration`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EpaStatus {
    /// Depth and normal are exact within [`EPA_TOLERANCE`].
    Converged,
    /// Iteration or face cap reached: the best face found is returned.
    NotConverged,
    /// The Minkowski difference is flat or empty (e.g. two flat hulls in one plane):
    /// no volume to expand; the result is a fallback estimate.
    Degenerate,
}

/// Result of [`epa_penetration`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EpaResult {
    /// Outcome.
    pub status: EpaStatus,
    /// Unit normal from A to B: translating B by `depth · normal` separates the cores.
    pub normal: Vec3,
    /// Penetration depth, metres (`>= 0`).
    pub depth: f32,
    /// Witness on A (its deepest point inside B).
    pub point_a: Vec3,
    /// Witness on B.
    pub point_b: Vec3,
    /// Iterations used.
    pub iterations: u32,
}

#[derive(Clone, Copy, Debug)]
struct Face {
    v: [u16; 3],
    n: Vec3,
    d: f32,
}

/// Penetration of overlapping cores, starting from GJK's final `simplex`.
///
/// Never loops more than [`EPA_MAX_ITERATIONS`]; failure is reported in the status.
#[must_use]
pub fn epa_penetration(
    a: &ConvexCore<'_>,
    pa: &Pose,
    b: &ConvexCore<'_>,
    pb: &Pose,
    simplex: &Simplex,
) -> EpaResult {
    let mut verts: Vec<SupportPoint> = simplex.v[..simplex.len].to_vec();
    let fallback = |status: EpaStatus, verts: &[SupportPoint]| {
        // Centre-to-centre direction as the least-bad normal.
        let n = (pb.translation - pa.translation)
            .try_normalize()
            .unwrap_or(Vec3::Y);
        let sp = support(a, pa, b, pb, n);
        let depth = sp.w.dot(n).max(0.0);
        let _ = verts;
        EpaResult {
            status,
            normal: n,
            depth,
            point_a: sp.a,
            point_b: sp.b,
            iterations: 0,
        }
    };
    if !blow_up(a, pa, b, pb, &mut verts) {
        return fallback(EpaStatus::Degenerate, &verts);
    }
    let interior = (verts[0].w + verts[1].w + verts[2].w + verts[3].w) * 0.25;
    let mut faces: Vec<Face> = Vec::with_capacity(64);
    let make = |verts: &[SupportPoint], i: u16, j: u16, k: u16| -> Option<Face> {
        let (p0, p1, p2) = (
            verts[i as usize].w,
            verts[j as usize].w,
            verts[k as usize].w,
        );
        let mut n = (p1 - p0).cross(p2 - p0);
        let len = n.length();
        if len.is_nan() || len <= 1e-12 {
            return None;
        }
        n /= len;
        let mut v = [i, j, k];
        if n.dot(p0 - interior) < 0.0 {
            n = -n;
            v.swap(1, 2);
        }
        Some(Face { v, n, d: n.dot(p0) })
    };
    for (i, j, k) in [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)] {
        match make(&verts, i, j, k) {
            Some(f) => faces.push(f),
            None => return fallback(EpaStatus::Degenerate, &verts),
        }
    }
    let mut status = EpaStatus::NotConverged;
    let mut iterations = 0;
    let mut best = faces[0];
    let mut edges: Vec<(u16, u16)> = Vec::with_capacity(32);
    while iterations < EPA_MAX_ITERATIONS {
        iterations += 1;
        let Some(fi) = (0..faces.len()).min_by(|&x, &y| faces[x].d.total_cmp(&faces[y].d)) else {
            break;
        };
        best = faces[fi];
        let w = support(a, pa, b, pb, best.n);
        let gain = w.w.dot(best.n) - best.d;
        if gain <= EPA_TOLERANCE * best.d.abs().max(1.0) {
            status = EpaStatus::Converged;
            break;
        }
        if faces.len() >= EPA_MAX_FACES || verts.len() >= u16::MAX as usize {
            break;
        }
        let wi = verts.len() as u16;
        verts.push(w);
        // Remove faces seeing w; collect the horizon.
        edges.clear();
        let mut k = 0;
        while k < faces.len() {
            let f = faces[k];
            if f.n.dot(w.w - verts[f.v[0] as usize].w) > 0.0 {
                for e in [(f.v[0], f.v[1]), (f.v[1], f.v[2]), (f.v[2], f.v[0])] {
                    if let Some(pos) = edges.iter().position(|&x| x == (e.1, e.0)) {
                        edges.swap_remove(pos);
                    } else {
                        edges.push(e);
                    }
                }
                faces.swap_remove(k);
            } else {
                k += 1;
            }
        }
        for &(i, j) in &edges {
            if let Some(f) = make(&verts, i, j, wi) {
                faces.push(f);
            }
        }
        if faces.is_empty() {
            break;
        }
    }
    // Witness points from the barycentric coordinates of the origin's projection.
    let (p0, p1, p2) = (
        verts[best.v[0] as usize],
        verts[best.v[1] as usize],
        verts[best.v[2] as usize],
    );
    let proj = best.n * best.d;
    let (_, bary, _) = closest_on_triangle(p0.w - proj, p1.w - proj, p2.w - proj);
    let point_a = p0.a * bary[0] + p1.a * bary[1] + p2.a * bary[2];
    let point_b = p0.b * bary[0] + p1.b * bary[1] + p2.b * bary[2];
    EpaResult {
        status,
        normal: best.n,
        depth: best.d.max(0.0),
        point_a,
        point_b,
        iterations,
    }
}

/// Grows a 1–3 vertex simplex into a tetrahedron with volume; false if the Minkowski
/// difference is flat along every tried direction.
fn blow_up(
    a: &ConvexCore<'_>,
    pa: &Pose,
    b: &ConvexCore<'_>,
    pb: &Pose,
    verts: &mut Vec<SupportPoint>,
) -> bool {
    const DIRS: [Vec3; 6] = [
        Vec3::X,
        Vec3::Y,
        Vec3::Z,
        Vec3::NEG_X,
        Vec3::NEG_Y,
        Vec3::NEG_Z,
    ];
    /// Minimum extent (metres) of a new simplex direction to count as non-degenerate.
    const MIN_LEN: f32 = 1e-6;
    if verts.is_empty() {
        verts.push(support(a, pa, b, pb, Vec3::X));
    }
    if verts.len() == 1 {
        let p = verts[0].w;
        for d in DIRS {
            let s = support(a, pa, b, pb, d);
            if s.w.distance(p) > MIN_LEN {
                verts.push(s);
                break;
            }
        }
        if verts.len() < 2 {
            return false;
        }
    }
    if verts.len() == 2 {
        let axis = (verts[1].w - verts[0].w).normalize();
        let u = axis.any_orthonormal_vector();
        let v = axis.cross(u);
        let mut found = false;
        for d in [u, v, -u, -v, (u + v).normalize(), (u - v).normalize()] {
            let s = support(a, pa, b, pb, d);
            let off = s.w - verts[0].w;
            if (off - axis * off.dot(axis)).length() > MIN_LEN {
                verts.push(s);
                found = true;
                break;
            }
        }
        if !found {
            return false;
        }
    }
    if verts.len() == 3 {
        let n = (verts[1].w - verts[0].w)
            .cross(verts[2].w - verts[0].w)
            .normalize_or_zero();
        if n == Vec3::ZERO {
            return false;
        }
        let mut found = false;
        for d in [n, -n] {
            let s = support(a, pa, b, pb, d);
            if (s.w - verts[0].w).dot(n).abs() > MIN_LEN {
                verts.push(s);
                found = true;
                break;
            }
        }
        if !found {
            return false;
        }
    }
    let v = &verts[..4];
    let vol = (v[1].w - v[0].w).dot((v[2].w - v[0].w).cross(v[3].w - v[0].w));
    vol.abs() > 1e-12
}
