//! [`load_model_source`]: a model file read on the CPU, by its extension.

use std::path::Path;

use super::gltf::GltfFileLease;
use super::import_settings::ImportSettings;
use super::model_load_error::ModelLoadError;
use super::model_source::ModelSource;
use super::sub_asset::SubAsset;

/// Reads the model at `path` (images not decoded): `.gltf` and `.glb` through the glTF
/// reader, one mesh of one when the path names it ([`SubAsset::Mesh`], `file.glb#mesh/N`);
/// anything else as OBJ (a file that is not names the line that is not OBJ). A glTF file
/// `lease` holds is read once for every load holding it.
pub(crate) fn load_model_source(
    path: &Path,
    settings: &ImportSettings,
    lease: Option<&GltfFileLease>,
) -> Result<ModelSource, ModelLoadError> {
    if let (file, Some(SubAsset::Mesh(index))) = SubAsset::split(path) {
        return super::gltf::load_gltf_mesh_source(&file, index, settings, lease);
    }
    if is_gltf(path) {
        super::gltf::load_gltf_source(path, settings, lease)
    } else {
        super::obj::load_obj_source(path, settings)
    }
}

/// Whether `path` names a glTF file (`.gltf` or `.glb`, any case).
#[must_use]
pub fn is_gltf(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("gltf") || e.eq_ignore_ascii_case("glb"))
}
