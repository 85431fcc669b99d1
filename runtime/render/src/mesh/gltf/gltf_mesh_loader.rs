//! [`load_gltf_mesh_source`]: one mesh of a glTF file (`file.glb#mesh/N`) as a
//! [`ModelSource`], for scenes whose entities each draw one mesh of the file.

use std::sync::Arc;

use glam::{Mat4, Vec3};

use super::gltf_file::GltfFile;
use super::gltf_material::convert_material;
use super::gltf_primitive::{read_primitive, Primitive};
use crate::asset_io::AssetWarning;
use crate::mesh::import_settings::ImportSettings;
use crate::mesh::model_load_error::ModelLoadError;
use crate::mesh::model_source::{ModelSource, PartSource};
use crate::mesh::up_axis::UpAxis;
use crate::model_material::UvTransform;

/// Reads mesh `mesh_index` of a glTF file read once for all its meshes ([`GltfFile`]): one part per triangle primitive, in
/// the mesh's own space (the entity that draws it carries the node's transform), with its
/// material; its images are decoded from the shared file. The file's extensions, skins and
/// animations are not reported here: the scene importer names each once for the whole file.
///
/// # Errors
/// [`ModelLoadError`] naming the file when it has no mesh `mesh_index`, or that mesh has no
/// triangles.
pub(crate) fn load_gltf_mesh_source(
    file: &Arc<GltfFile>,
    mesh_index: usize,
    settings: &ImportSettings,
) -> Result<ModelSource, ModelLoadError> {
    let path = file.path.as_path();
    let gltf_error = |message: String| ModelLoadError::Gltf {
        path: path.to_owned(),
        message,
    };
    let document = &file.document;
    let Some(mesh) = document.meshes().nth(mesh_index) else {
        return Err(gltf_error(format!(
            "it has {} mesh(es), so there is no mesh {mesh_index} (`#mesh/{mesh_index}`)",
            document.meshes().len()
        )));
    };
    let buffers = &file.buffers;
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
        match read_primitive(&primitive, buffers, uv_set, uv) {
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
    // The file's images are decoded from the shared read, once for all its meshes.
    source.gltf = Some(file.clone());
    Ok(source)
}
