//! [`load_gltf_mesh_source`]: one mesh of a glTF file (`file.glb#mesh/N`) as a
//! [`ModelSource`], for scenes whose entities each draw one mesh of the file.

use std::path::Path;

use glam::{Mat4, Vec3};

use super::gltf_buffers::{image_bytes, load_buffers};
use super::gltf_material::convert_material;
use super::gltf_primitive::{read_primitive, Primitive};
use crate::asset_io::{read_asset_file, AssetWarning, MAX_ASSET_FILE_BYTES};
use crate::mesh::import_settings::ImportSettings;
use crate::mesh::model_load_error::ModelLoadError;
use crate::mesh::model_source::{ModelSource, PartSource};
use crate::mesh::up_axis::UpAxis;
use crate::model_material::{ImageSource, UvTransform};

/// Reads mesh `mesh_index` of the glTF file at `path`: one part per triangle primitive, in
/// the mesh's own space (the entity that draws it carries the node's transform), with its
/// material and the images inside the file it uses. The file's extensions, skins and
/// animations are not reported here: the scene importer names each once for the whole file.
///
/// # Errors
/// [`ModelLoadError`] naming the file when it cannot be read, is not glTF, has no mesh
/// `mesh_index`, or that mesh has no triangles.
pub(crate) fn load_gltf_mesh_source(
    path: &Path,
    mesh_index: usize,
    settings: &ImportSettings,
) -> Result<ModelSource, ModelLoadError> {
    let gltf_error = |message: String| ModelLoadError::Gltf {
        path: path.to_owned(),
        message,
    };
    let bytes =
        read_asset_file(path, MAX_ASSET_FILE_BYTES).map_err(|source| ModelLoadError::Read {
            path: path.to_owned(),
            source,
        })?;
    let body = bytes.strip_prefix(&[0xEF, 0xBB, 0xBF]).unwrap_or(&bytes);
    // Validated: every index the document holds names something that exists. (The scene
    // importer has already named any required extension Onyx lacks.)
    let gltf = gltf::Gltf::from_slice(body).map_err(|e| {
        gltf_error(format!(
            "it is not a valid glTF 2.0 file ({e}); re-export it"
        ))
    })?;
    let document = &gltf.document;
    let Some(mesh) = document.meshes().nth(mesh_index) else {
        return Err(gltf_error(format!(
            "it has {} mesh(es), so there is no mesh {mesh_index} (`#mesh/{mesh_index}`)",
            document.meshes().len()
        )));
    };
    let folder = path.parent().unwrap_or(Path::new(""));
    let buffers = load_buffers(document, gltf.blob.as_deref(), folder).map_err(gltf_error)?;
    let to_onyx = Mat4::from_scale(Vec3::splat(settings.scale))
        * match settings.up_axis {
            UpAxis::Y => Mat4::IDENTITY,
            UpAxis::Z => Mat4::from_rotation_x(-std::f32::consts::FRAC_PI_2),
        };
    let mut parts = Vec::new();
    let mut skipped = Vec::new();
    for primitive in mesh.primitives() {
        let material = primitive
            .material()
            .index()
            .map(|_| convert_material(&primitive.material(), path))
            .unwrap_or_default();
        let (uv_set, uv) = material
            .base_color_texture
            .as_ref()
            .map_or((0, UvTransform::IDENTITY), |t| (t.uv_set, t.transform));
        match read_primitive(&primitive, &buffers, uv_set, uv) {
            Primitive::Mesh(data) => parts.push(PartSource {
                name: mesh
                    .name()
                    .map_or_else(|| format!("mesh{mesh_index}"), str::to_owned),
                mesh: data,
                material,
                material_missing: false,
                transform: to_onyx,
            }),
            Primitive::NotTriangles(kind) => {
                skipped.push(format!("primitive {} ({kind})", primitive.index()));
            }
            Primitive::Invalid(why) => {
                skipped.push(format!("primitive {} ({why})", primitive.index()));
            }
        }
    }
    let mut warnings = Vec::new();
    if !skipped.is_empty() {
        warnings.push(AssetWarning::new(
            path,
            None,
            format!(
                "mesh {mesh_index}: {} primitive(s) not drawn: {}",
                skipped.len(),
                skipped.join(", ")
            ),
        ));
    }
    if parts.is_empty() {
        return Err(gltf_error(format!(
            "mesh {mesh_index} has no triangles to draw ({})",
            skipped.join(", ")
        )));
    }
    let mut source = ModelSource::new(path.to_owned(), parts, Vec::new(), warnings);
    for image in document.images() {
        let key = ImageSource::Embedded {
            model: path.to_owned(),
            index: image.index(),
        };
        let used = source.parts.iter().any(|p| {
            p.material
                .base_color_texture
                .as_ref()
                .is_some_and(|t| t.image == key)
        });
        if !used {
            continue;
        }
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
    Ok(source)
}
