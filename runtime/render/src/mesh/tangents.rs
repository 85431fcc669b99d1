//! MikkTSpace tangents for a [`MeshData`], through `bevy_mikktspace` (the reference
//! implementation, as Blender and glTF exporters bake normal maps against).

use glam::Vec3;

use super::mesh_data::MeshData;

/// Adapter from an indexed triangle list to the MikkTSpace interface.
struct Triangles<'a> {
    mesh: &'a mut MeshData,
}

impl Triangles<'_> {
    fn vertex(&self, face: usize, vert: usize) -> &super::vertex::Vertex {
        let index = self.mesh.indices[face * 3 + vert] as usize;
        &self.mesh.vertices[index]
    }
}

impl bevy_mikktspace::Geometry for Triangles<'_> {
    fn num_faces(&self) -> usize {
        self.mesh.indices.len() / 3
    }

    fn num_vertices_of_face(&self, _face: usize) -> usize {
        3
    }

    fn position(&self, face: usize, vert: usize) -> [f32; 3] {
        self.vertex(face, vert).position
    }

    fn normal(&self, face: usize, vert: usize) -> [f32; 3] {
        self.vertex(face, vert).normal
    }

    fn tex_coord(&self, face: usize, vert: usize) -> [f32; 2] {
        // MikkTSpace expects v up (OpenGL); Onyx's and glTF's v runs down the image. Flipped,
        // the bitangent points up the image, where normal maps put +Y (green).
        let [u, v] = self.vertex(face, vert).uv;
        [u, 1.0 - v]
    }

    fn set_tangent_encoded(&mut self, tangent: [f32; 4], face: usize, vert: usize) {
        let index = self.mesh.indices[face * 3 + vert] as usize;
        // Vertices shared by triangles that disagree keep the last one; MikkTSpace agrees
        // wherever position, normal and uv agree, which is what sharing means.
        self.mesh.vertices[index].tangent = tangent;
    }
}

impl MeshData {
    /// Whether every vertex has a tangent (`w` = ±1).
    #[must_use]
    pub fn has_tangents(&self) -> bool {
        self.vertices.iter().all(|v| v.tangent[3] != 0.0)
    }

    /// Computes MikkTSpace tangents from positions, normals and texture coordinates. Where
    /// they cannot be computed (no texture coordinates, degenerate triangles) a tangent
    /// perpendicular to the normal is chosen, so normal maps stay well-defined.
    pub fn generate_tangents(&mut self) {
        if !self.is_valid() {
            return;
        }
        for vertex in &mut self.vertices {
            vertex.tangent = [0.0; 4];
        }
        let generated = bevy_mikktspace::generate_tangents(&mut Triangles { mesh: self });
        if !generated {
            tracing::debug!("MikkTSpace could not generate tangents; using perpendicular ones");
        }
        for vertex in &mut self.vertices {
            let n = Vec3::from(vertex.normal);
            let t = Vec3::from_slice(&vertex.tangent[..3]);
            let t = (t - n * n.dot(t))
                .try_normalize()
                .unwrap_or_else(|| n.any_orthonormal_vector());
            let w = if vertex.tangent[3] < 0.0 { -1.0 } else { 1.0 };
            vertex.tangent = t.extend(w).to_array();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A plane in XZ with u along +X and v (down the image) along +Z: the tangent points
    /// along +X and the bitangent up the image, -Z.
    #[test]
    fn tangents_follow_u_and_bitangents_point_up_the_image() {
        let mut plane = MeshData::plane(2.0);
        plane.generate_tangents();
        assert!(plane.has_tangents());
        for v in &plane.vertices {
            let t = Vec3::from_slice(&v.tangent[..3]);
            let n = Vec3::from(v.normal);
            assert!(t.dot(Vec3::X) > 0.99, "tangent {t:?}");
            assert!(n.dot(t).abs() < 1e-4);
            let bitangent = n.cross(t) * v.tangent[3];
            assert!(bitangent.dot(Vec3::NEG_Z) > 0.99, "bitangent {bitangent:?}");
        }
    }

    #[test]
    fn a_mesh_without_uvs_still_gets_unit_perpendicular_tangents() {
        let mut cube = MeshData::cube(1.0);
        for v in &mut cube.vertices {
            v.uv = [0.0, 0.0];
        }
        cube.generate_tangents();
        for v in &cube.vertices {
            let t = Vec3::from_slice(&v.tangent[..3]);
            assert!((t.length() - 1.0).abs() < 1e-4 && Vec3::from(v.normal).dot(t).abs() < 1e-4);
            assert!(v.tangent[3].abs() == 1.0);
        }
    }
}
