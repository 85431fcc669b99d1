//! [`load_gltf_source`]: a glTF or GLB file into a [`ModelSource`] on the CPU.

use std::collections::HashSet;
use std::sync::Arc;

use glam::{Mat4, Quat, Vec3};

use super::gltf_file::{GltfFile, SUPPORTED_EXTENSIONS};
use super::gltf_material::convert_material;
use super::gltf_primitive::{read_primitive, Primitive};
use crate::asset_io::AssetWarning;
use crate::mesh::import_settings::ImportSettings;
use crate::mesh::model_load_error::ModelLoadError;
use crate::mesh::model_source::{ModelSource, PartSource};
use crate::mesh::up_axis::UpAxis;
use crate::model_material::{ModelMaterial, UvTransform};

/// Reads a glTF 2.0 file (read by [`GltfFile::read`], which refuses an extension the file
/// requires that Onyx lacks): the default scene's (else the first scene's, else every root
/// node's) meshes, one part per triangle primitive at its node's world transform, with its
/// material. An extension the file merely uses is warned once; skins and morph targets load in their bind pose with one warning each.
pub(crate) fn load_gltf_source(
    file: &Arc<GltfFile>,
    settings: &ImportSettings,
) -> Result<ModelSource, ModelLoadError> {
    let path = file.path.as_path();
    let document = &file.document;
    let mut warnings = Vec::new();
    for extension in document
        .extensions_used()
        .filter(|e| !SUPPORTED_EXTENSIONS.contains(e))
    {
        warnings.push(AssetWarning::new(
            path,
            None,
            format!("extension `{extension}` is not supported; what it adds is ignored"),
        ));
    }
    if document.skins().next().is_some() {
        warnings.push(AssetWarning::new(
            path,
            None,
            "skins (skeletal animation) are not supported yet; the meshes are shown in their bind pose",
        ));
    }
    if document
        .meshes()
        .any(|m| m.primitives().any(|p| p.morph_targets().next().is_some()))
    {
        warnings.push(AssetWarning::new(
            path,
            None,
            "morph targets are not supported yet; the meshes are shown without them",
        ));
    }
    if document.animations().next().is_some() {
        warnings.push(AssetWarning::new(
            path,
            None,
            "animations are not played when the file is drawn as one model",
        ));
    }
    let buffers = &file.buffers;
    let materials: Vec<ModelMaterial> = document
        .materials()
        .map(|m| convert_material(&m, path))
        .collect();

    let to_onyx = Mat4::from_scale(Vec3::splat(settings.scale))
        * match settings.up_axis {
            UpAxis::Y => Mat4::IDENTITY,
            UpAxis::Z => Mat4::from_rotation_x(-std::f32::consts::FRAC_PI_2),
        };
    let roots: Vec<gltf::Node<'_>> = match document
        .default_scene()
        .or_else(|| document.scenes().next())
    {
        Some(scene) => scene.nodes().collect(),
        None => {
            let children: HashSet<usize> = document
                .nodes()
                .flat_map(|n| n.children().map(|c| c.index()).collect::<Vec<_>>())
                .collect();
            document
                .nodes()
                .filter(|n| !children.contains(&n.index()))
                .collect()
        }
    };
    let mut parts = Vec::new();
    let mut skipped: Vec<String> = Vec::new();
    let mut stack: Vec<(gltf::Node<'_>, Mat4, usize)> =
        roots.into_iter().map(|n| (n, to_onyx, 0)).collect();
    let mut visited = HashSet::new();
    while let Some((node, parent, depth)) = stack.pop() {
        // The crate validates indices, not cycles: a node seen twice is not walked again.
        if !visited.insert(node.index()) || depth > 256 {
            continue;
        }
        let world = parent * node_matrix(&node);
        if let Some(mesh) = node.mesh() {
            for primitive in mesh.primitives() {
                let material = primitive
                    .material()
                    .index()
                    .and_then(|i| materials.get(i).cloned())
                    .unwrap_or_default();
                let (uv_set, uv) = material
                    .base_color_texture
                    .as_ref()
                    .map_or((0, UvTransform::IDENTITY), |t| (t.uv_set, t.transform));
                match read_primitive(&primitive, buffers, uv_set, uv) {
                    Primitive::Mesh(data) => parts.push(PartSource {
                        name: node
                            .name()
                            .or(mesh.name())
                            .map_or_else(|| format!("node{}", node.index()), str::to_owned),
                        mesh: data,
                        material,
                        material_missing: false,
                        transform: world,
                    }),
                    Primitive::NotTriangles(kind) => skipped.push(format!(
                        "mesh {} primitive {} ({kind})",
                        mesh.index(),
                        primitive.index()
                    )),
                    Primitive::Invalid(why) => skipped.push(format!(
                        "mesh {} primitive {} ({why})",
                        mesh.index(),
                        primitive.index()
                    )),
                }
            }
        }
        stack.extend(node.children().map(|c| (c, world, depth + 1)));
    }
    if !skipped.is_empty() {
        warnings.push(AssetWarning::new(
            path,
            None,
            format!(
                "{} primitive(s) not drawn: {}",
                skipped.len(),
                skipped.join(", ")
            ),
        ));
    }
    if parts.is_empty() {
        return Err(ModelLoadError::Empty {
            path: path.to_owned(),
        });
    }
    let mut source = ModelSource::new(path.to_owned(), parts, Vec::new(), warnings);
    // Images inside the file are decoded from it, with the others.
    source.gltf = Some(file.clone());
    tracing::debug!(path = %path.display(), parts = source.parts.len(), "glTF read");
    Ok(source)
}

/// A node's local transform (a matrix, or translation × rotation × scale).
fn node_matrix(node: &gltf::Node<'_>) -> Mat4 {
    let (t, r, s) = node.transform().decomposed();
    let matrix = match node.transform() {
        gltf::scene::Transform::Matrix { matrix } => Mat4::from_cols_array_2d(&matrix),
        gltf::scene::Transform::Decomposed { .. } => Mat4::from_scale_rotation_translation(
            Vec3::from(s),
            Quat::from_array(r).normalize(),
            Vec3::from(t),
        ),
    };
    if matrix.is_finite() {
        matrix
    } else {
        Mat4::IDENTITY
    }
}
