//! [`read_primitive`]: one glTF primitive's accessors as a [`MeshData`] (tangents kept when
//! the file has them).

use glam::Vec3;

use crate::mesh::mesh_data::MeshData;
use crate::mesh::vertex::Vertex;
use crate::model_material::UvTransform;

/// What a primitive gave: its mesh, or why it was skipped.
pub(crate) enum Primitive {
    Mesh(MeshData),
    /// Points or lines: not drawn.
    NotTriangles(&'static str),
    /// No positions, or indices out of range.
    Invalid(String),
}

/// Reads positions, normals (flat ones generated when absent, as glTF asks), UV set
/// `uv_set` transformed by `uv` (the base-colour texture transform, so the renderer draws
/// it) and indices (strips and fans unrolled). Sparse accessors are resolved by `gltf`'s
/// reader.
pub(crate) fn read_primitive(
    primitive: &gltf::Primitive<'_>,
    buffers: &[Vec<u8>],
    uv_set: u32,
    uv: UvTransform,
) -> Primitive {
    use gltf::mesh::Mode;
    let reader = primitive.reader(|buffer| buffers.get(buffer.index()).map(Vec::as_slice));
    let Some(positions) = reader.read_positions() else {
        return Primitive::Invalid("it has no POSITION attribute".to_owned());
    };
    let positions: Vec<[f32; 3]> = positions.collect();
    let count = positions.len() as u32;
    let raw: Vec<u32> = match reader.read_indices() {
        Some(indices) => indices.into_u32().collect(),
        None => (0..count).collect(),
    };
    let indices: Vec<u32> = match primitive.mode() {
        Mode::Triangles => raw[..raw.len() / 3 * 3].to_vec(),
        Mode::TriangleStrip => (2..raw.len())
            .flat_map(|i| {
                if i % 2 == 0 {
                    [raw[i - 2], raw[i - 1], raw[i]]
                } else {
                    [raw[i - 1], raw[i - 2], raw[i]]
                }
            })
            .collect(),
        Mode::TriangleFan => (2..raw.len())
            .flat_map(|i| [raw[0], raw[i - 1], raw[i]])
            .collect(),
        Mode::Points => return Primitive::NotTriangles("points"),
        Mode::Lines | Mode::LineLoop | Mode::LineStrip => return Primitive::NotTriangles("lines"),
    };
    if let Some(bad) = indices.iter().find(|&&i| i >= count) {
        return Primitive::Invalid(format!("index {bad} is past its {count} vertices"));
    }
    let normals: Option<Vec<[f32; 3]>> = reader.read_normals().map(Iterator::collect);
    // The file's tangents when it has them (with normals); otherwise they are generated.
    let tangents: Option<Vec<[f32; 4]>> = reader
        .read_tangents()
        .map(Iterator::collect)
        .filter(|t: &Vec<[f32; 4]>| t.len() == positions.len() && uv.rotation == 0.0);
    let uvs: Option<Vec<[f32; 2]>> = reader
        .read_tex_coords(uv_set)
        .map(|t| t.into_f32().map(|c| uv.apply(c)).collect());
    let uv_at = |i: usize| {
        uvs.as_ref()
            .and_then(|u| u.get(i).copied())
            .unwrap_or([0.0, 0.0])
    };
    let clean = |p: [f32; 3]| p.map(|c| if c.is_finite() { c } else { 0.0 });
    let mesh = match normals {
        Some(normals) if normals.len() == positions.len() => MeshData {
            vertices: positions
                .iter()
                .zip(&normals)
                .enumerate()
                .map(|(i, (&p, &n))| {
                    let n = Vec3::from(n).try_normalize().unwrap_or(Vec3::Y);
                    let vertex = Vertex::new(clean(p), n.to_array(), uv_at(i));
                    match tangents.as_ref().and_then(|t| t.get(i)) {
                        Some(&[x, y, z, w])
                            if [x, y, z, w].iter().all(|c| c.is_finite()) && w != 0.0 =>
                        {
                            vertex.with_tangent([x, y, z, w.signum()])
                        }
                        _ => vertex,
                    }
                })
                .collect(),
            indices,
        },
        // No normals: flat ones, so every triangle gets its own three vertices.
        _ => {
            let mut mesh = MeshData::default();
            for t in indices.chunks_exact(3) {
                let p = [t[0], t[1], t[2]].map(|i| Vec3::from(clean(positions[i as usize])));
                let n = (p[1] - p[0])
                    .cross(p[2] - p[0])
                    .try_normalize()
                    .unwrap_or(Vec3::Y);
                for (k, &i) in t.iter().enumerate() {
                    mesh.indices.push(mesh.vertices.len() as u32);
                    mesh.vertices.push(Vertex::new(
                        p[k].to_array(),
                        n.to_array(),
                        uv_at(i as usize),
                    ));
                }
            }
            mesh
        }
    };
    if mesh.is_valid() {
        Primitive::Mesh(mesh)
    } else {
        Primitive::Invalid("it has no complete triangle".to_owned())
    }
}
