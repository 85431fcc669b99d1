//! [`build_parts`]: an [`ObjDocument`]'s faces as indexed triangle meshes, one per part.

use std::collections::HashMap;
use std::path::Path;

use glam::{DVec3, Vec3};

use super::obj_document::{ObjDocument, NONE};
use super::polygon::triangulate_polygon;
use crate::asset_io::AssetWarning;
use crate::mesh::corner_normals::corner_normals;
use crate::mesh::import_settings::ImportSettings;
use crate::mesh::mesh_data::MeshData;
use crate::mesh::vertex::Vertex;
use crate::model_material::UvTransform;

/// One part's triangles, single-indexed.
pub(crate) struct BuiltPart {
    /// Index into the document's parts.
    pub(crate) key: usize,
    pub(crate) mesh: MeshData,
}

/// Builds every part with faces: polygons triangulated (ear clipping), missing normals
/// generated (smoothing groups, else `settings.normals`), positions turned and scaled by
/// `settings`, texture coordinates transformed by `uv_of(part)` (the material's `-s`/`-o`)
/// and flipped to a top-left origin; parts without any get box-projected ones.
pub(crate) fn build_parts(
    doc: &ObjDocument,
    settings: &ImportSettings,
    uv_of: impl Fn(usize) -> UvTransform,
    path: &Path,
    warnings: &mut Vec<AssetWarning>,
) -> Vec<BuiltPart> {
    let mut faces_of: Vec<Vec<usize>> = vec![Vec::new(); doc.parts.len()];
    for (i, face) in doc.faces.iter().enumerate() {
        faces_of[face.part as usize].push(i);
    }
    let file_positions: Vec<Vec3> = doc.positions.iter().map(|&p| Vec3::from(p)).collect();
    let mut fans = 0usize;
    let mut parts = Vec::new();
    let mut polygon: Vec<DVec3> = Vec::new();
    let mut cut: Vec<[u32; 3]> = Vec::new();
    for (key, faces) in faces_of.iter().enumerate() {
        if faces.is_empty() {
            continue;
        }
        // Triangles as corner indices into `doc.corners`, with their smoothing group.
        let mut triangles: Vec<[u32; 3]> = Vec::new();
        let mut groups: Vec<u32> = Vec::new();
        for &fi in faces {
            let face = doc.faces[fi];
            let corners = &doc.corners[face.first as usize..(face.first + face.count) as usize];
            polygon.clear();
            polygon.extend(
                corners
                    .iter()
                    .map(|c| Vec3::from(doc.positions[c.v as usize]).as_dvec3()),
            );
            if triangulate_polygon(&polygon, &mut cut) {
                fans += 1;
            }
            for t in &cut {
                triangles.push(t.map(|k| face.first + k));
                groups.push(face.smoothing);
            }
        }
        let by_position: Vec<[u32; 3]> = triangles
            .iter()
            .map(|t| t.map(|c| doc.corners[c as usize].v))
            .collect();
        let needs_normals = triangles
            .iter()
            .flatten()
            .any(|&c| doc.corners[c as usize].vn == NONE);
        let generated = if needs_normals {
            corner_normals(
                &file_positions,
                &by_position,
                doc.has_smoothing.then_some(groups.as_slice()),
                settings.normals,
            )
        } else {
            Vec::new()
        };
        let uv = uv_of(key);
        let has_uvs = triangles
            .iter()
            .flatten()
            .any(|&c| doc.corners[c as usize].vt != NONE);
        let mut mesh = MeshData::default();
        let mut seen: HashMap<(u32, u32, [u32; 3]), u32> = HashMap::new();
        for (k, &c) in triangles.iter().flatten().enumerate() {
            let corner = doc.corners[c as usize];
            let normal = if corner.vn != NONE {
                let n = Vec3::from(doc.normals[corner.vn as usize]);
                n.try_normalize()
                    .unwrap_or(generated.get(k).copied().unwrap_or(Vec3::Y))
            } else {
                generated[k]
            };
            let id = (corner.v, corner.vt, normal.to_array().map(f32::to_bits));
            let next = mesh.vertices.len() as u32;
            let index = *seen.entry(id).or_insert_with(|| {
                let texcoord = if corner.vt == NONE {
                    [0.0, 0.0]
                } else {
                    let [u, v] = doc.texcoords[corner.vt as usize];
                    // MTL's -s/-o act in OBJ's space (v up); then v flips to a top-left origin.
                    let [u, v] = [
                        u * uv.scale[0] + uv.offset[0],
                        v * uv.scale[1] + uv.offset[1],
                    ];
                    [u, 1.0 - v]
                };
                mesh.vertices.push(Vertex::new(
                    settings.position(doc.positions[corner.v as usize]),
                    settings.normal(normal.to_array()),
                    texcoord,
                ));
                next
            });
            mesh.indices.push(index);
        }
        if !has_uvs {
            mesh.compute_box_uvs();
        }
        parts.push(BuiltPart { key, mesh });
    }
    if fans > 0 {
        warnings.push(AssetWarning::new(
            path,
            None,
            format!("{fans} polygon(s) are self-intersecting or degenerate; they were cut as fans and may look wrong"),
        ));
    }
    parts
}
