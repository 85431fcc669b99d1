//! Box–box contact: separating-axis test over 15 axes, then face clipping or edge–edge points.

use glam::{Mat3, Vec3};

use super::polygon_clip::clip_features;
use super::raw_manifold::RawManifold;
use crate::pose::Pose;
use crate::shape::ConvexCore;

/// A face axis is kept unless an edge–edge axis separates more by this much, metres.
/// Prevents flip-flopping between face and edge manifolds of resting boxes. Bounded `[0, 0.01]`.
pub const BOX_EDGE_BIAS: f32 = 0.001;

/// Face of B replaces face of A as reference only when it separates more by this, metres.
pub const BOX_FACE_BIAS: f32 = 0.0005;

/// Edge pairs whose axis is within this cosine of a face normal of either box are left to
/// the face axes: both edges then lie nearly in that face, a face contact. Two boxes resting
/// face on face with a relative tilt (a stack settling under an off-centre load tips its
/// boxes by 1e-2 rad at 30 Hz × 2) have edge axes that mix the two tilts, and one of them
/// measured less overlap than either face by more than [`BOX_EDGE_BIAS`]: the face became
/// a one-point edge contact for a step with a normal tilted like neither face, and its
/// sideways push set a frictionless stack sliding apart, for ever. cos(0.1 rad).
pub const BOX_EDGE_FACE_COS: f32 = 0.995_004_2;

/// Edge pairs whose cross product is shorter than this are parallel and skipped.
pub const BOX_PARALLEL_EPSILON: f32 = 1e-5;

/// Box A (half extents `ha` at `pa`) against box B (`hb` at `pb`).
#[must_use]
pub(crate) fn box_box(
    ha: Vec3,
    pa: &Pose,
    hb: Vec3,
    pb: &Pose,
    margin: f32,
    scratch: &mut (Vec<Vec3>, Vec<Vec3>),
) -> Option<RawManifold> {
    let rel = pa.inv_mul(pb);
    let r = Mat3::from_quat(rel.rotation);
    let t = rel.translation;
    let bx = [r.x_axis, r.y_axis, r.z_axis];
    let absr = [bx[0].abs(), bx[1].abs(), bx[2].abs()];
    // Face axes of A.
    let mut best_a = (f32::MIN, 0usize);
    for i in 0..3 {
        let rb = hb.x * absr[0][i] + hb.y * absr[1][i] + hb.z * absr[2][i];
        let sep = t[i].abs() - ha[i] - rb;
        if sep > margin {
            return None;
        }
        if sep > best_a.0 {
            best_a = (sep, i);
        }
    }
    let mut best_b = (f32::MIN, 0usize);
    for j in 0..3 {
        let ra = ha.dot(absr[j]);
        let sep = t.dot(bx[j]).abs() - ra - hb[j];
        if sep > margin {
            return None;
        }
        if sep > best_b.0 {
            best_b = (sep, j);
        }
    }
    let mut best_e = (f32::MIN, 0usize, 0usize, Vec3::ZERO);
    for i in 0..3 {
        for j in 0..3 {
            let mut e = Vec3::ZERO;
            e[i] = 1.0;
            let axis = e.cross(bx[j]);
            let len = axis.length();
            if len < BOX_PARALLEL_EPSILON {
                continue;
            }
            let axis = axis / len;
            // An edge pair whose axis lies along a face normal of either box is a face
            // touching an edge or a face (see `BOX_EDGE_FACE_COS`): the face axis measures it.
            if axis.abs().max_element() > BOX_EDGE_FACE_COS
                || bx.iter().any(|b| b.dot(axis).abs() > BOX_EDGE_FACE_COS)
            {
                continue;
            }
            let ra = ha.dot(axis.abs());
            let rb = hb.x * bx[0].dot(axis).abs()
                + hb.y * bx[1].dot(axis).abs()
                + hb.z * bx[2].dot(axis).abs();
            let sep = t.dot(axis).abs() - ra - rb;
            if sep > margin {
                return None;
            }
            if sep > best_e.0 {
                let oriented = if t.dot(axis) >= 0.0 { axis } else { -axis };
                best_e = (sep, i, j, oriented);
            }
        }
    }
    let face_sep = best_a.0.max(best_b.0);
    let to_frame = |m: &mut RawManifold| {
        m.normal = pa.rotation * m.normal;
        for p in &mut m.points {
            p.point = pa.transform_point(p.point);
        }
    };
    if best_e.0 > face_sep + BOX_EDGE_BIAS {
        let (_, i, j, n) = best_e;
        // Supporting edges.
        let ca = ConvexCore::Cuboid(ha).support(n);
        let mut ea = Vec3::ZERO;
        ea[i] = 1.0;
        let cb_local = ConvexCore::Cuboid(hb).support(rel.inverse_transform_vector(-n));
        // Edge segments centred at the support corners' projections.
        let a0 = Vec3::from_array({
            let mut v = ca.to_array();
            v[i] = -ha[i];
            v
        });
        let a1 = Vec3::from_array({
            let mut v = ca.to_array();
            v[i] = ha[i];
            v
        });
        let mut b_lo = cb_local;
        b_lo[j] = -hb[j];
        let mut b_hi = cb_local;
        b_hi[j] = hb[j];
        let (b0, b1) = (rel.transform_point(b_lo), rel.transform_point(b_hi));
        let (p, q) = super::capsule_contacts::closest_segment_segment(a0, a1, b0, b1);
        let sep = n.dot(q - p);
        if sep > margin {
            return None;
        }
        let mut m = RawManifold::single(n, (p + q) * 0.5, sep, 0x8000 | (i as u32) << 2 | j as u32);
        to_frame(&mut m);
        return Some(m);
    }
    let (ref_is_a, axis) = if best_b.0 > best_a.0 + BOX_FACE_BIAS {
        (false, best_b.1)
    } else {
        (true, best_a.1)
    };
    let (refp, incp) = (&mut scratch.0, &mut scratch.1);
    let (ref_normal, mut m) = if ref_is_a {
        let mut n = Vec3::ZERO;
        n[axis] = if t[axis] >= 0.0 { 1.0 } else { -1.0 };
        ConvexCore::Cuboid(ha).support_feature(n, refp);
        ConvexCore::Cuboid(hb).support_feature(rel.inverse_transform_vector(-n), incp);
        for p in incp.iter_mut() {
            *p = rel.transform_point(*p);
        }
        (n, RawManifold::new(n))
    } else {
        // Outward normal of B's reference face points toward A.
        let nb_local = {
            let mut n = Vec3::ZERO;
            n[axis] = if t.dot(bx[axis]) >= 0.0 { -1.0 } else { 1.0 };
            n
        };
        ConvexCore::Cuboid(hb).support_feature(nb_local, refp);
        for p in refp.iter_mut() {
            *p = rel.transform_point(*p);
        }
        let nb = rel.rotation * nb_local;
        ConvexCore::Cuboid(ha).support_feature(-nb, incp);
        (nb, RawManifold::new(-nb))
    };
    let id_base = if ref_is_a { 0 } else { 0x4000 } | (axis as u32) << 12;
    clip_features(refp, ref_normal, 0.0, incp, 0.0, margin, id_base, &mut m);
    if m.points.is_empty() {
        return None;
    }
    to_frame(&mut m);
    Some(m)
}

#[cfg(test)]
mod tests {
    use glam::Quat;

    use super::*;

    /// Boxes resting face on face, tilted by up to 0.03 rad each about horizontal axes and
    /// offset by up to a third of their width, 1 cm into each other: every pair touches as a
    /// face (a stack settling under its off-centre loads). Before edge axes along a face
    /// normal were left to the faces, some of them became a one-point edge contact with a
    /// normal that mixed the two tilts.
    #[test]
    fn tilted_faces_resting_on_each_other_touch_as_faces() {
        let mut seed = 7u64;
        let mut rand = |lo: f32, hi: f32| {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            lo + (hi - lo) * ((seed >> 40) as f32 / (1u64 << 24) as f32)
        };
        let mut scratch = (Vec::new(), Vec::new());
        let mut one_point = Vec::new();
        for _ in 0..2000 {
            let ha = Vec3::new(rand(0.35, 0.6), rand(0.3, 0.5), rand(0.35, 0.6));
            let hb = Vec3::new(rand(0.35, 0.6), rand(0.3, 0.5), rand(0.35, 0.6));
            let tilt = |r: &mut dyn FnMut(f32, f32) -> f32| {
                Quat::from_scaled_axis(Vec3::new(r(-0.03, 0.03), 0.0, r(-0.03, 0.03)))
            };
            let qa = tilt(&mut rand);
            let qb = tilt(&mut rand);
            let offset = Vec3::new(rand(-0.3, 0.3) * ha.x, 0.0, rand(-0.3, 0.3) * ha.z);
            let pa = Pose::new(Vec3::ZERO, qa);
            let up = qa * Vec3::Y;
            let pb = Pose::new(qa * offset + up * (ha.y + hb.y - 0.01), qb);
            let m = box_box(ha, &pa, hb, &pb, 0.02, &mut scratch).expect("the boxes overlap");
            if m.points.len() < 3 {
                one_point.push((ha, hb, qa, qb, offset, m.points.len(), m.normal));
            }
        }
        assert!(
            one_point.is_empty(),
            "{} of 2000, first {:?}",
            one_point.len(),
            one_point[0]
        );
    }
}
