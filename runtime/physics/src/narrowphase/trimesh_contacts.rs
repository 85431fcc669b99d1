//! Convex shapes against a static triangle mesh: one manifold per touched triangle.

use glam::Vec3;

use super::convex_convex::{convex_convex, ClipScratch};
use super::narrow_stats::NarrowStats;
use super::raw_manifold::RawManifold;
use crate::pose::Pose;
use crate::shape::{ConvexCore, Shape, TriMesh};

/// Cap on triangles examined per convex–mesh pair per step (bounded work for huge shapes
/// overlapping dense meshes). Extra triangles are skipped and counted as EPA failures so the
/// truncation is visible.
pub const TRIMESH_MAX_TRIANGLES_PER_PAIR: usize = 256;

/// Mesh (shape A at `pm`) against convex `shape` (B at `pc`). Appends manifolds, normals
/// from the mesh toward the convex shape.
#[allow(clippy::too_many_arguments)]
pub(crate) fn trimesh_convex(
    mesh: &TriMesh,
    pm: &Pose,
    shape: &Shape,
    pc: &Pose,
    margin: f32,
    out: &mut Vec<RawManifold>,
    stats: &mut NarrowStats,
    scratch: &mut ClipScratch,
) {
    let Some((core, radius)) = shape.convex_core() else {
        return;
    };
    // Convex bounds in the mesh frame.
    let rel = pm.inv_mul(pc);
    let bounds = shape.aabb(&rel).expanded(margin);
    let mut tris: Vec<usize> = Vec::new();
    mesh.for_each_in_aabb(&bounds, |t| tris.push(t));
    if tris.len() > TRIMESH_MAX_TRIANGLES_PER_PAIR {
        stats.epa_failures += 1;
        tris.truncate(TRIMESH_MAX_TRIANGLES_PER_PAIR);
    }
    for t in tris {
        let [a, b, c] = mesh.triangle(t);
        let tri = ConvexCore::Triangle([a, b, c]);
        if let Some(mut m) = convex_convex(&tri, pm, 0.0, &core, pc, radius, margin, stats, scratch)
        {
            // One-sided sanity: keep the normal on the side where the shape's centre lies.
            let n_tri = pm.rotation * (b - a).cross(c - a).normalize_or_zero();
            let center_side = n_tri.dot(pc.translation - pm.transform_point(a));
            if n_tri != Vec3::ZERO && m.normal.dot(n_tri) * center_side < -0.5 * center_side.abs() {
                continue;
            }
            for p in &mut m.points {
                p.id = (t as u32) << 8 | (p.id & 0xFF);
            }
            out.push(m);
        }
    }
}
