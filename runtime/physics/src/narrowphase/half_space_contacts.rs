//! Half space (plane) against convex cores: vertices of the supporting feature below the plane.

use glam::Vec3;

use super::raw_manifold::{RawManifold, RawPoint};
use crate::pose::Pose;
use crate::shape::ConvexCore;

/// Plane (shape A: outward `normal` in its frame at `pp`) against a convex core (shape B at
/// `pc`, rounded by `radius`). Normal from plane to B.
#[must_use]
pub(crate) fn half_space_convex(
    normal: Vec3,
    pp: &Pose,
    core: &ConvexCore<'_>,
    pc: &Pose,
    radius: f32,
    margin: f32,
    scratch: &mut Vec<Vec3>,
) -> Option<RawManifold> {
    let n = pp.rotation * normal;
    let origin = pp.translation;
    let local_dir = pc.inverse_transform_vector(-n);
    core.support_feature(local_dir, scratch);
    let deepest = core.support(local_dir);
    if !scratch.contains(&deepest) {
        scratch.push(deepest);
    }
    let mut m = RawManifold::new(n);
    for (i, v) in scratch.iter().enumerate() {
        let p = pc.transform_point(*v);
        let sep = n.dot(p - origin) - radius;
        if sep <= margin {
            let surface = p - n * radius;
            m.points.push(RawPoint {
                point: surface - n * (sep * 0.5),
                separation: sep,
                id: i as u32,
            });
        }
    }
    if m.points.is_empty() {
        return None;
    }
    Some(m)
}
