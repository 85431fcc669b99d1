//! [`MeshData`]: an indexed triangle list on the CPU.

use glam::Vec3;

use super::vertex::Vertex;

/// An indexed triangle list on the CPU, counter-clockwise front faces. Upload it with
/// [`crate::Renderer::add_mesh`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    /// Vertices.
    pub vertices: Vec<Vertex>,
    /// Three indices per triangle.
    pub indices: Vec<u32>,
}

impl MeshData {
    /// Number of triangles.
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// Whether the mesh is usable: at least one triangle, every index in range.
    #[must_use]
    pub fn is_valid(&self) -> bool {
        !self.indices.is_empty()
            && self.indices.len().is_multiple_of(3)
            && self
                .indices
                .iter()
                .all(|&i| (i as usize) < self.vertices.len())
    }

    /// Replaces every normal by the area-weighted average of the faces that share the vertex
    /// (smooth shading). Degenerate vertices get +Y.
    pub fn compute_smooth_normals(&mut self) {
        let mut sums = vec![Vec3::ZERO; self.vertices.len()];
        for tri in self.indices.chunks_exact(3) {
            let [a, b, c] = [tri[0] as usize, tri[1] as usize, tri[2] as usize];
            let (Some(va), Some(vb), Some(vc)) = (
                self.vertices.get(a),
                self.vertices.get(b),
                self.vertices.get(c),
            ) else {
                continue;
            };
            let pa = Vec3::from(va.position);
            let face = (Vec3::from(vb.position) - pa).cross(Vec3::from(vc.position) - pa);
            for i in [a, b, c] {
                sums[i] += face;
            }
        }
        for (vertex, sum) in self.vertices.iter_mut().zip(sums) {
            vertex.normal = sum.normalize_or(Vec3::Y).to_array();
        }
    }

    /// Sets texture coordinates by box projection: each vertex takes the two position
    /// components across its normal's dominant axis, so a texture repeats every metre. Used
    /// for files that have no texture coordinates, so a (fallback) texture still shows.
    pub fn compute_box_uvs(&mut self) {
        for vertex in &mut self.vertices {
            let [x, y, z] = vertex.position;
            let n = Vec3::from(vertex.normal).abs();
            vertex.uv = if n.x >= n.y && n.x >= n.z {
                [z, 1.0 - y]
            } else if n.y >= n.z {
                [x, z]
            } else {
                [x, 1.0 - y]
            };
        }
    }

    /// Bounding sphere (centre, radius) around the vertices, model space: centre of the
    /// axis-aligned box, radius to the farthest vertex.
    #[must_use]
    pub fn bounding_sphere(&self) -> (Vec3, f32) {
        let mut min = Vec3::splat(f32::INFINITY);
        let mut max = Vec3::splat(f32::NEG_INFINITY);
        for v in &self.vertices {
            let p = Vec3::from(v.position);
            min = min.min(p);
            max = max.max(p);
        }
        if !min.is_finite() || !max.is_finite() {
            return (Vec3::ZERO, 0.0);
        }
        let center = (min + max) * 0.5;
        let radius = self
            .vertices
            .iter()
            .map(|v| Vec3::from(v.position).distance(center))
            .fold(0.0_f32, f32::max);
        (center, radius)
    }
}
