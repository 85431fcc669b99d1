//! GJK: distance, closest points and overlap of two convex cores ([`gjk_distance`]).

use glam::Vec3;

use crate::pose::Pose;
use crate::shape::ConvexCore;

/// Iteration cap of GJK. Bounded `[8, 256]`: polytopes with V vertices converge in about
/// V iterations, curved cores in ~20; hitting the cap reports [`GjkStatus::NotConverged`].
pub const GJK_MAX_ITERATIONS: u32 = 64;

/// Relative convergence tolerance: stop when `|v|² - v·w <= GJK_RELATIVE_TOLERANCE · |v|²`.
/// Bounded `[1e-7, 1e-3]`: lower costs iterations (and may not be reachable in f32),
/// higher returns less exact distances.
pub const GJK_RELATIVE_TOLERANCE: f32 = 1e-6;

/// Absolute tolerance, metres: a distance below this counts as touching/overlapping.
/// Bounded `[1e-7, 1e-4]`.
pub const GJK_ABSOLUTE_TOLERANCE: f32 = 1e-6;

/// Outcome of [`gjk_distance`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GjkStatus {
    /// Cores are apart; distance and points are valid.
    Separated,
    /// Cores overlap or touch (distance below [`GJK_ABSOLUTE_TOLERANCE`]); run EPA for depth.
    Overlapping,
    /// Iteration cap reached: the distance is the best upper bound found.
    NotConverged,
}

/// A vertex of the Minkowski difference with its witnesses on A and B.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SupportPoint {
    /// `a - b`.
    pub w: Vec3,
    /// Point on A.
    pub a: Vec3,
    /// Point on B.
    pub b: Vec3,
}

/// Up to four support points; the final GJK simplex (seed for EPA).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Simplex {
    /// Vertices (first `len` valid).
    pub v: [SupportPoint; 4],
    /// Number of valid vertices.
    pub len: usize,
}

/// Result of [`gjk_distance`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GjkResult {
    /// Outcome.
    pub status: GjkStatus,
    /// Distance between the cores (0 when overlapping), metres.
    pub distance: f32,
    /// Closest point on A.
    pub point_a: Vec3,
    /// Closest point on B.
    pub point_b: Vec3,
    /// Unit direction from A to B (zero when overlapping).
    pub normal: Vec3,
    /// Iterations used.
    pub iterations: u32,
    /// Final simplex.
    pub simplex: Simplex,
}

/// Support point of `A - B` along `d` with shapes placed at their poses.
#[inline]
pub(crate) fn support(
    a: &ConvexCore<'_>,
    pa: &Pose,
    b: &ConvexCore<'_>,
    pb: &Pose,
    d: Vec3,
) -> SupportPoint {
    let sa = pa.transform_point(a.support(pa.inverse_transform_vector(d)));
    let sb = pb.transform_point(b.support(pb.inverse_transform_vector(-d)));
    SupportPoint {
        w: sa - sb,
        a: sa,
        b: sb,
    }
}

/// Closest-face candidate: squared distance, point, weights, kept vertices, face index.
type FaceHit = (f32, Vec3, [f32; 3], [bool; 3], usize);

/// Closest point to the origin on the simplex; shrinks it to the supporting sub-simplex and
/// returns `(point, barycentric weights, contains_origin)`.
fn closest_on_simplex(s: &mut Simplex) -> (Vec3, [f32; 4], bool) {
    match s.len {
        1 => (s.v[0].w, [1.0, 0.0, 0.0, 0.0], false),
        2 => {
            let (a, b) = (s.v[0].w, s.v[1].w);
            let ab = b - a;
            let den = ab.length_squared();
            let t = if den > 0.0 {
                (-a.dot(ab) / den).clamp(0.0, 1.0)
            } else {
                0.0
            };
            if t <= 0.0 {
                s.len = 1;
                (a, [1.0, 0.0, 0.0, 0.0], false)
            } else if t >= 1.0 {
                s.v[0] = s.v[1];
                s.len = 1;
                (b, [1.0, 0.0, 0.0, 0.0], false)
            } else {
                (a + ab * t, [1.0 - t, t, 0.0, 0.0], false)
            }
        }
        3 => {
            let (p, bary, keep) = closest_on_triangle(s.v[0].w, s.v[1].w, s.v[2].w);
            let (v, bary) = compact(s, &keep[..3], &bary[..3]);
            let _ = v;
            (p, bary, false)
        }
        _ => {
            let (a, b, c, d) = (s.v[0].w, s.v[1].w, s.v[2].w, s.v[3].w);
            let vol = (b - a).dot((c - a).cross(d - a));
            let scale = (b - a).length() * (c - a).length() * (d - a).length();
            // Faces opposite each vertex: (b,c,d), (a,c,d), (a,b,d), (a,b,c).
            let faces = [[1usize, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]];
            if vol.abs() > 1e-7 * scale {
                // Origin inside when it lies on the same side of each face as the opposite vertex.
                let mut inside = true;
                for (opp, f) in faces.iter().enumerate() {
                    let (p0, p1, p2) = (s.v[f[0]].w, s.v[f[1]].w, s.v[f[2]].w);
                    let n = (p1 - p0).cross(p2 - p0);
                    let so = n.dot(-p0);
                    let sv = n.dot(s.v[opp].w - p0);
                    if so * sv < 0.0 {
                        inside = false;
                        break;
                    }
                }
                if inside {
                    return (Vec3::ZERO, [0.0; 4], true);
                }
            }
            // Closest over the faces.
            let mut best: Option<FaceHit> = None;
            for (fi, f) in faces.iter().enumerate() {
                let (p, bary, keep) = closest_on_triangle(s.v[f[0]].w, s.v[f[1]].w, s.v[f[2]].w);
                let d2 = p.length_squared();
                if best.is_none_or(|b| d2 < b.0) {
                    best = Some((d2, p, bary, keep, fi));
                }
            }
            let (_, p, bary, keep, fi) =
                best.unwrap_or((0.0, Vec3::ZERO, [1.0, 0.0, 0.0], [true, false, false], 3));
            let f = faces[fi];
            let tri = [s.v[f[0]], s.v[f[1]], s.v[f[2]]];
            s.v[0] = tri[0];
            s.v[1] = tri[1];
            s.v[2] = tri[2];
            s.len = 3;
            let (_, bary) = compact(s, &keep, &bary);
            (p, bary, false)
        }
    }
}

/// Drops simplex vertices whose `keep` flag is false; returns compacted weights.
fn compact(s: &mut Simplex, keep: &[bool], bary: &[f32]) -> (usize, [f32; 4]) {
    let mut out = [0.0f32; 4];
    let mut n = 0;
    for i in 0..keep.len() {
        if keep[i] {
            s.v[n] = s.v[i];
            out[n] = bary[i];
            n += 1;
        }
    }
    s.len = n;
    (n, out)
}

/// Closest point to the origin on triangle `abc` (Voronoi regions): point, weights and
/// which vertices support it.
pub(crate) fn closest_on_triangle(a: Vec3, b: Vec3, c: Vec3) -> (Vec3, [f32; 3], [bool; 3]) {
    let ab = b - a;
    let ac = c - a;
    let ap = -a;
    let d1 = ab.dot(ap);
    let d2 = ac.dot(ap);
    if d1 <= 0.0 && d2 <= 0.0 {
        return (a, [1.0, 0.0, 0.0], [true, false, false]);
    }
    let bp = -b;
    let d3 = ab.dot(bp);
    let d4 = ac.dot(bp);
    if d3 >= 0.0 && d4 <= d3 {
        return (b, [0.0, 1.0, 0.0], [false, true, false]);
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let den = d1 - d3;
        let v = if den != 0.0 { d1 / den } else { 0.0 };
        return (a + ab * v, [1.0 - v, v, 0.0], [true, true, false]);
    }
    let cp = -c;
    let d5 = ab.dot(cp);
    let d6 = ac.dot(cp);
    if d6 >= 0.0 && d5 <= d6 {
        return (c, [0.0, 0.0, 1.0], [false, false, true]);
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let den = d2 - d6;
        let w = if den != 0.0 { d2 / den } else { 0.0 };
        return (a + ac * w, [1.0 - w, 0.0, w], [true, false, true]);
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let den = (d4 - d3) + (d5 - d6);
        let w = if den != 0.0 { (d4 - d3) / den } else { 0.0 };
        return (b + (c - b) * w, [0.0, 1.0 - w, w], [false, true, true]);
    }
    let sum = va + vb + vc;
    if sum.abs() <= f32::MIN_POSITIVE {
        // Degenerate (zero-area) triangle: fall back to the best edge.
        let mut best = (a, [1.0, 0.0, 0.0], [true, false, false]);
        let mut bd = a.length_squared();
        for (p, q, ip, iq) in [(a, b, 0, 1), (b, c, 1, 2), (a, c, 0, 2)] {
            let e = q - p;
            let den = e.length_squared();
            let t = if den > 0.0 {
                (-p.dot(e) / den).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let x = p + e * t;
            if x.length_squared() < bd {
                bd = x.length_squared();
                let mut w = [0.0; 3];
                let mut k = [false; 3];
                w[ip] = 1.0 - t;
                w[iq] = t;
                k[ip] = true;
                k[iq] = true;
                best = (x, w, k);
            }
        }
        return best;
    }
    let den = 1.0 / sum;
    let v = vb * den;
    let w = vc * den;
    (a + ab * v + ac * w, [1.0 - v - w, v, w], [true, true, true])
}

/// GJK distance between convex cores `a` at `pa` and `b` at `pb` (radii excluded).
///
/// Never loops more than [`GJK_MAX_ITERATIONS`]; non-convergence is reported in the status.
#[must_use]
pub fn gjk_distance(a: &ConvexCore<'_>, pa: &Pose, b: &ConvexCore<'_>, pb: &Pose) -> GjkResult {
    let mut d0 = pb.translation - pa.translation;
    if d0.length_squared() < 1e-12 {
        d0 = Vec3::X;
    }
    let first = support(a, pa, b, pb, -d0);
    let mut s = Simplex {
        v: [first; 4],
        len: 1,
    };
    let mut v = first.w;
    let mut bary = [1.0f32, 0.0, 0.0, 0.0];
    let mut prev_d2 = f32::MAX;
    let mut status = GjkStatus::NotConverged;
    let mut iterations = 0;
    while iterations < GJK_MAX_ITERATIONS {
        iterations += 1;
        let d2 = v.length_squared();
        if d2 <= GJK_ABSOLUTE_TOLERANCE * GJK_ABSOLUTE_TOLERANCE {
            status = GjkStatus::Overlapping;
            break;
        }
        let w = support(a, pa, b, pb, -v);
        // Progress check: no support point gets meaningfully closer.
        if d2 - v.dot(w.w) <= GJK_RELATIVE_TOLERANCE * d2 {
            status = GjkStatus::Separated;
            break;
        }
        // Duplicate vertex: cycling, we are converged within float precision.
        if s.v[..s.len]
            .iter()
            .any(|p| p.w.distance_squared(w.w) <= 1e-12 * d2.max(1.0))
        {
            status = GjkStatus::Separated;
            break;
        }
        let saved = s;
        s.v[s.len] = w;
        s.len += 1;
        let (p, bw, inside) = closest_on_simplex(&mut s);
        if inside {
            status = GjkStatus::Overlapping;
            v = Vec3::ZERO;
            break;
        }
        let nd2 = p.length_squared();
        if nd2 >= prev_d2.min(d2) {
            // No progress (numerical floor): keep the previous answer.
            s = saved;
            status = GjkStatus::Separated;
            break;
        }
        prev_d2 = d2;
        v = p;
        bary = bw;
    }
    if status == GjkStatus::Overlapping {
        return GjkResult {
            status,
            distance: 0.0,
            point_a: witness(&s, &bary, true),
            point_b: witness(&s, &bary, false),
            normal: Vec3::ZERO,
            iterations,
            simplex: s,
        };
    }
    let pa_w = witness(&s, &bary, true);
    let pb_w = witness(&s, &bary, false);
    let dist = v.length();
    GjkResult {
        status,
        distance: dist,
        point_a: pa_w,
        point_b: pb_w,
        normal: if dist > 0.0 { -v / dist } else { Vec3::ZERO },
        iterations,
        simplex: s,
    }
}

fn witness(s: &Simplex, bary: &[f32; 4], on_a: bool) -> Vec3 {
    let mut p = Vec3::ZERO;
    let mut wsum = 0.0;
    for (v, &w) in s.v[..s.len].iter().zip(bary) {
        p += if on_a { v.a } else { v.b } * w;
        wsum += w;
    }
    if wsum > 0.0 {
        p / wsum
    } else if on_a {
        s.v[0].a
    } else {
        s.v[0].b
    }
}

/// True when the cores at their poses overlap or touch (distance at most `margin`).
#[must_use]
pub fn gjk_intersects(
    a: &ConvexCore<'_>,
    pa: &Pose,
    b: &ConvexCore<'_>,
    pb: &Pose,
    margin: f32,
) -> bool {
    let r = gjk_distance(a, pa, b, pb);
    r.status == GjkStatus::Overlapping || r.distance <= margin
}
