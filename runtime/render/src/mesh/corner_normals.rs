//! [`corner_normals`]: normals for triangles that have none, honouring smoothing groups and
//! a crease angle.

use std::collections::HashMap;

use glam::Vec3;

use super::normal_mode::NormalMode;

/// One normal per triangle corner (`3 * triangles.len()` of them), for triangles indexing
/// `positions`.
///
/// A corner averages the area-weighted normals of the triangles around its position (points
/// at exactly the same place count as one, so a file that repeats positions still smooths)
/// that it is smoothed with:
/// - with `smoothing` groups (OBJ `s`), the triangles of its own non-zero group; group 0
///   (`s off`) is flat;
/// - without, the triangles within `mode`'s crease angle of its own.
///
/// A zero-area triangle gets +Y rather than NaN.
pub(crate) fn corner_normals(
    positions: &[Vec3],
    triangles: &[[u32; 3]],
    smoothing: Option<&[u32]>,
    mode: NormalMode,
) -> Vec<Vec3> {
    let weighted: Vec<Vec3> = triangles
        .iter()
        .map(|t| {
            let p = |i: u32| positions.get(i as usize).copied().unwrap_or(Vec3::ZERO);
            (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0]))
        })
        .collect();
    let unit: Vec<Vec3> = weighted.iter().map(|n| n.normalize_or_zero()).collect();
    let min_cos = mode.min_cos();

    // Welded position id of every corner, and the triangles around each id (CSR).
    let mut weld: HashMap<[u32; 3], u32> = HashMap::new();
    let ids: Vec<u32> = positions
        .iter()
        .map(|p| {
            let next = weld.len() as u32;
            *weld.entry(p.to_array().map(f32::to_bits)).or_insert(next)
        })
        .collect();
    let corner_id = |i: u32| ids.get(i as usize).copied().unwrap_or(0) as usize;
    let mut start = vec![0u32; weld.len() + 1];
    for t in triangles {
        for &i in t {
            start[corner_id(i) + 1] += 1;
        }
    }
    for k in 1..start.len() {
        start[k] += start[k - 1];
    }
    let mut fill = start.clone();
    let mut around = vec![0u32; triangles.len() * 3];
    for (ti, t) in triangles.iter().enumerate() {
        for &i in t {
            let slot = &mut fill[corner_id(i)];
            around[*slot as usize] = ti as u32;
            *slot += 1;
        }
    }

    let mut out = Vec::with_capacity(triangles.len() * 3);
    for (ti, t) in triangles.iter().enumerate() {
        let own = unit[ti];
        let group = smoothing.map(|g| g.get(ti).copied().unwrap_or(0));
        for &i in t {
            let id = corner_id(i);
            let mut sum = Vec3::ZERO;
            if group == Some(0) || (min_cos >= 1.0 && group.is_none()) {
                sum = weighted[ti];
            } else {
                for &other in &around[start[id] as usize..start[id + 1] as usize] {
                    let o = other as usize;
                    let smoothed = match (group, smoothing) {
                        (Some(g), Some(groups)) => groups.get(o).copied() == Some(g),
                        _ => o == ti || own.dot(unit[o]) >= min_cos,
                    };
                    if smoothed {
                        sum += weighted[o];
                    }
                }
            }
            out.push(
                sum.try_normalize()
                    .unwrap_or(if own == Vec3::ZERO { Vec3::Y } else { own }),
            );
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two triangles folded 90° along the X axis: a floor (+Y) and a wall (+Z).
    fn fold() -> (Vec<Vec3>, Vec<[u32; 3]>) {
        let positions = vec![
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 0.0, -1.0),
            Vec3::new(0.0, 1.0, 0.0),
        ];
        (positions, vec![[0, 1, 2], [0, 1, 3]])
    }

    #[test]
    fn a_crease_sharper_than_the_angle_stays_sharp() {
        let (p, t) = fold();
        let sharp = corner_normals(&p, &t, None, NormalMode::default());
        assert!(
            sharp[..3].iter().all(|n| n.abs_diff_eq(Vec3::Y, 1e-6)),
            "{sharp:?}"
        );
        assert!(
            sharp[3..].iter().all(|n| n.abs_diff_eq(Vec3::Z, 1e-6)),
            "{sharp:?}"
        );
        let round = corner_normals(&p, &t, None, NormalMode::Smooth);
        let shared = (Vec3::Y + Vec3::Z).normalize();
        // Corner 0 and corner 1 of the floor lie on the shared edge.
        assert!(round[0].abs_diff_eq(shared, 1e-6), "{round:?}");
        assert!(
            round[2].abs_diff_eq(Vec3::Y, 1e-6),
            "off the edge: {round:?}"
        );
    }

    #[test]
    fn smoothing_groups_decide_over_the_angle() {
        let (p, t) = fold();
        let same = corner_normals(&p, &t, Some(&[1, 1]), NormalMode::Flat);
        assert!(same[0].abs_diff_eq((Vec3::Y + Vec3::Z).normalize(), 1e-6));
        let off = corner_normals(&p, &t, Some(&[0, 0]), NormalMode::Smooth);
        assert!(off[0].abs_diff_eq(Vec3::Y, 1e-6) && off[3].abs_diff_eq(Vec3::Z, 1e-6));
    }
}
