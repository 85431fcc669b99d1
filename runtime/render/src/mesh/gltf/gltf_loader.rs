//! [`load_gltf_source`]: a glTF or GLB file into a [`ModelSource`] on the CPU.

use std::collections::HashSet;
use std::path::Path;

use glam::{Mat4, Quat, Vec3};

use super::gltf_buffers::{image_bytes, load_buffers};
use super::gltf_material::convert_material;
use super::gltf_primitive::{read_primitive, Primitive};
use crate::asset_io::{read_asset_file, AssetWarning, MAX_ASSET_FILE_BYTES};
use crate::mesh::import_settings::ImportSettings;
use crate::mesh::model_load_error::ModelLoadError;
use crate::mesh::model_source::{ModelSource, PartSource};
use crate::mesh::up_axis::UpAxis;
use crate::model_material::{ImageSource, ModelMaterial, UvTransform};

/// Extensions whose data Onyx reads.
const SUPPORTED_EXTENSIONS: [&str; 4] = [
    "KHR_lights_punctual",
    "KHR_texture_transform",
    "KHR_materials_emissive_strength",
    "KHR_materials_unlit",
];

/// Reads a glTF 2.0 file: the default scene's (else the first scene's, else every root
/// node's) meshes, one part per triangle primitive at its node's world transform, with its
/// material. An extension the file requires that Onyx lacks is an error; one it merely uses
/// is warned once; skins and morph targets load in their bind pose with one warning each.
pub(crate) fn load_gltf_source(
    path: &Path,
    settings: &ImportSettings,
) -> Result<ModelSource, ModelLoadError> {
    let bytes =
        read_asset_file(path, MAX_ASSET_FILE_BYTES).map_err(|source| ModelLoadError::Read {
            path: path.to_owned(),
            source,
        })?;
    let gltf_error = |message: String| ModelLoadError::Gltf {
        path: path.to_owned(),
        message,
    };
    // A UTF-8 byte-order mark is not JSON; some exporters write one.
    let body = bytes.strip_prefix(&[0xEF, 0xBB, 0xBF]).unwrap_or(&bytes);
    let invalid = |e: gltf::Error| {
        gltf_error(format!(
            "it is not a valid glTF 2.0 file ({e}); re-export it"
        ))
    };
    // Required extensions first: the crate's validation refuses ones it lacks with a
    // message that does not say what to do.
    let unchecked = gltf::Gltf::from_slice_without_validation(body).map_err(invalid)?;
    if let Some(extension) = unchecked
        .document
        .extensions_required()
        .find(|e| !SUPPORTED_EXTENSIONS.contains(e))
    {
        return Err(ModelLoadError::RequiredExtension {
            path: path.to_owned(),
            extension: extension.to_owned(),
        });
    }
    drop(unchecked);
    // Validated: every index the document holds names something that exists.
    let gltf = gltf::Gltf::from_slice(body).map_err(invalid)?;
    let document = &gltf.document;
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
    let folder = path.parent().unwrap_or(Path::new(""));
    let buffers = load_buffers(document, gltf.blob.as_deref(), folder).map_err(gltf_error)?;
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
                match read_primitive(&primitive, &buffers, uv_set, uv) {
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
    // Images inside the file: their encoded bytes, decoded with the others.
    for image in document.images() {
        let key = ImageSource::Embedded {
            model: path.to_owned(),
            index: image.index(),
        };
        let used = source.parts.iter().any(|p| {
            let m = &p.material;
            [
                &m.base_color_texture,
                &m.metallic_roughness_texture,
                &m.normal_texture,
                &m.occlusion_texture,
                &m.emissive_texture,
            ]
            .into_iter()
            .flatten()
            .any(|t| t.image == key)
        });
        if used {
            match image_bytes(&image, &buffers, folder) {
                Ok(bytes) => {
                    source.encoded.insert(key, bytes);
                }
                Err(message) => source.warnings.push(AssetWarning::new(
                    path,
                    None,
                    format!("image {}: {message}", image.index()),
                )),
            }
        }
    }
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
