//! Convex shapes against a static triangle mesh: one manifold per touched triangle.

use glam::Vec3;

use super::closest_approach::{closest_miss_of_cores, Passing};
use super::convex_convex::{convex_convex, ClipScratch};
use super::narrow_stats::NarrowStats;
use super::raw_manifold::RawManifold;
use crate::pose::Pose;
use crate::shape::{ConvexCore, Shape, TriMesh};

/// Cap on triangles examined per convex–mesh pair per step (bounded work for huge shapes
/// overlapping dense meshes). Extra triangles are skipped and counted as EPA failures so the
/// truncation is visible.
pub const TRIMESH_MAX_TRIANGLES_PER_PAIR: usize = 256;

/// Two triangles' manifolds whose normals agree within this cosine are one face's and are
/// merged (see [`trimesh_convex`]): about 0.5°, the tilt a soft face under an off-centre
/// load never reaches, well under the crease between a floor and a ramp.
pub const TRIMESH_COPLANAR_COS: f32 = 0.99996;

/// Points of merged manifolds closer than this fraction of the convex shape's reach are one
/// point (the corners a face shares along the triangles' common edge, clipped twice).
pub const TRIMESH_SAME_POINT_FRACTION: f32 = 1e-3;

/// Mesh (shape A at `pm`) against convex `shape` (B at `pc`). Appends manifolds, normals
/// from the mesh toward the convex shape.
///
/// Manifolds of coplanar triangles are merged into one, as one face (reduced to four points
/// with the others by `collide`). A body resting across the shared edge of two triangles
/// otherwise had a manifold per triangle, each clipped to its half of the face, with the
/// corners on the shared edge in both: those corners had twice the stiffness of the others
/// and the face rocked on them.
/// A 1 mm box on the diagonal of a two-triangle floor drifted 7 % of its size in 10 s at
/// fast, and a column of three 1 cm cubes on it 36 % of a cube at balanced.
///
/// With `passing` (the convex shape's motion relative to the mesh over the step), a
/// triangle whose contact would hold the shape short of its straight path, and which the
/// shape only goes by ([`closest_miss_of_cores`]), has none: a ball gliding 1 cm over a mesh
/// box's edge at 5 m/s met the edge along a normal pointing back along its path, and was
/// braked to 1.7 m/s and thrown up.
#[allow(clippy::too_many_arguments)]
pub(crate) fn trimesh_convex(
    mesh: &TriMesh,
    pm: &Pose,
    shape: &Shape,
    pc: &Pose,
    margin: f32,
    passing: Option<Passing>,
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
    let first = out.len();
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
            if let Some(passing) = passing {
                let held = m
                    .points
                    .iter()
                    .any(|p| p.separation + m.normal.dot(passing.closing) * passing.ahead < 0.0);
                if held
                    && closest_miss_of_cores((&tri, 0.0, pm), (&core, radius, pc), passing)
                        .is_some()
                {
                    continue;
                }
            }
            for p in &mut m.points {
                p.id = (t as u32) << 8 | (p.id & 0xFF);
            }
            out.push(m);
        }
    }
    merge_coplanar(
        out,
        first,
        TRIMESH_SAME_POINT_FRACTION * core.reach().max(radius),
    );
}

/// Merges the manifolds of `out[first..]` whose normals agree within
/// [`TRIMESH_COPLANAR_COS`] into the first of them, dropping points within `same` metres of
/// one already there (`collide` reduces each to four points).
fn merge_coplanar(out: &mut Vec<RawManifold>, first: usize, same: f32) {
    if out.len() - first < 2 {
        return;
    }
    let same2 = same * same;
    let mut i = first;
    while i < out.len() {
        let mut j = i + 1;
        while j < out.len() {
            if out[j].normal.dot(out[i].normal) >= TRIMESH_COPLANAR_COS {
                let other = out.swap_remove(j);
                for p in other.points {
                    if out[i]
                        .points
                        .iter()
                        .all(|q| q.point.distance_squared(p.point) > same2)
                    {
                        out[i].points.push(p);
                    }
                }
            } else {
                j += 1;
            }
        }
        i += 1;
    }
}
