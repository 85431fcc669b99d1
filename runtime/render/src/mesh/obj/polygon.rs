//! [`triangulate_polygon`]: a planar polygon of any shape as triangles.

use glam::DVec3;

/// Triangles (corner indices into `points`) covering a simple polygon, convex or concave
/// (a washer's outline, an L-shaped floor), with the polygon's own winding. Ear clipping
/// (the `earcut` crate) on the polygon projected onto its best-fit plane; triangles, quads
/// and polygons earcut cannot cut (self-intersecting, degenerate) fall back to a fan, which
/// is exact for convex ones. Returns the triangles and whether the fan fallback was used.
pub(crate) fn triangulate_polygon(points: &[DVec3], out: &mut Vec<[u32; 3]>) -> bool {
    out.clear();
    let n = points.len();
    if n < 3 {
        return false;
    }
    let fan = |out: &mut Vec<[u32; 3]>| {
        out.clear();
        out.extend((1..n as u32 - 1).map(|i| [0, i, i + 1]));
    };
    if n == 3 {
        fan(out);
        return false;
    }
    // Newell's normal: robust for non-planar and concave polygons.
    let mut normal = DVec3::ZERO;
    for i in 0..n {
        let (a, b) = (points[i], points[(i + 1) % n]);
        normal += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    let Some(normal) = normal.try_normalize() else {
        fan(out);
        return true;
    };
    if n == 4 && is_convex(points, normal) {
        fan(out);
        return false;
    }
    let u = normal.any_orthonormal_vector();
    let v = normal.cross(u);
    let flat: Vec<[f64; 2]> = points.iter().map(|p| [p.dot(u), p.dot(v)]).collect();
    let mut indices: Vec<u32> = Vec::with_capacity(3 * (n - 2));
    earcut::Earcut::new().earcut(flat.iter().copied(), &[] as &[u32], &mut indices);
    if indices.len() != 3 * (n - 2) {
        fan(out);
        return true;
    }
    for t in indices.chunks_exact(3) {
        let [a, b, c] = [t[0], t[1], t[2]];
        let face = (points[b as usize] - points[a as usize])
            .cross(points[c as usize] - points[a as usize]);
        out.push(if face.dot(normal) >= 0.0 {
            [a, b, c]
        } else {
            [a, c, b]
        });
    }
    false
}

fn is_convex(points: &[DVec3], normal: DVec3) -> bool {
    let n = points.len();
    (0..n).all(|i| {
        let (a, b, c) = (points[i], points[(i + 1) % n], points[(i + 2) % n]);
        (b - a).cross(c - b).dot(normal) >= 0.0
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(points: &[DVec3], tris: &[[u32; 3]]) -> f64 {
        tris.iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| points[i as usize]);
                (b - a).cross(c - a).z * 0.5
            })
            .sum()
    }

    #[test]
    fn an_l_shape_is_cut_into_triangles_inside_it() {
        // Area 3: a 2×2 square missing its top-right quarter, counter-clockwise.
        let l: Vec<DVec3> = [(2., 1.), (1., 1.), (1., 2.), (0., 2.), (0., 0.), (2., 0.)]
            .iter()
            .map(|&(x, y)| DVec3::new(x, y, 0.0))
            .collect();
        let mut tris = Vec::new();
        assert!(!triangulate_polygon(&l, &mut tris));
        assert_eq!(tris.len(), 4);
        // A fan from corner 0 would start with a clockwise triangle over the missing
        // quarter; ear clipping covers exactly the outline, every triangle counter-clockwise.
        assert!((area(&l, &tris) - 3.0).abs() < 1e-9, "{tris:?}");
        assert!(tris.iter().all(|t| area(&l, &[*t]) > 0.0), "{tris:?}");
    }
}
