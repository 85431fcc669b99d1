//! [`GltfDocument`]: a glTF file opened for import, its required extensions checked and
//! each feature Onyx does not bring in named once.

use std::path::{Path, PathBuf};

use onyx_render::asset_io::{read_asset_file, MAX_ASSET_FILE_BYTES};

use super::GltfImportError;

/// Extensions whose data Onyx reads (the renderer reads the material ones; the importer
/// reads lights).
pub const SUPPORTED_EXTENSIONS: [&str; 4] = [
    "KHR_lights_punctual",
    "KHR_texture_transform",
    "KHR_materials_emissive_strength",
    "KHR_materials_unlit",
];

/// A parsed, validated glTF file (every index it holds names something that exists) and
/// the warnings about what it uses that Onyx leaves out, one per feature.
pub struct GltfDocument {
    /// The file.
    pub path: PathBuf,
    /// The JSON document and the GLB binary chunk.
    pub gltf: gltf::Gltf,
    /// One sentence per feature left out (an extension, skins, morph targets).
    pub warnings: Vec<String>,
}

impl GltfDocument {
    /// Reads and checks the file at `path` (a regular file only: a device or FIFO is refused).
    ///
    /// # Errors
    /// [`GltfImportError`] when it cannot be read, is not glTF 2.0, or requires an extension
    /// Onyx lacks.
    pub fn open(path: &Path) -> Result<Self, GltfImportError> {
        let bytes = read_asset_file(path, MAX_ASSET_FILE_BYTES).map_err(|source| {
            GltfImportError::Read {
                path: path.to_owned(),
                message: source.to_string(),
            }
        })?;
        // A UTF-8 byte-order mark is not JSON; some exporters write one.
        let body = bytes.strip_prefix(&[0xEF, 0xBB, 0xBF]).unwrap_or(&bytes);
        let invalid = |e: gltf::Error| GltfImportError::Invalid {
            path: path.to_owned(),
            message: e.to_string(),
        };
        // Required extensions first: validation refuses ones the crate lacks with a message
        // that does not say what to do.
        let unchecked = gltf::Gltf::from_slice_without_validation(body).map_err(invalid)?;
        if let Some(extension) = unchecked
            .document
            .extensions_required()
            .find(|e| !SUPPORTED_EXTENSIONS.contains(e))
        {
            return Err(GltfImportError::RequiredExtension {
                path: path.to_owned(),
                extension: extension.to_owned(),
            });
        }
        drop(unchecked);
        let gltf = gltf::Gltf::from_slice(body).map_err(invalid)?;
        let warnings = left_out(&gltf.document);
        Ok(Self {
            path: path.to_owned(),
            gltf,
            warnings,
        })
    }

    /// The JSON document.
    pub fn document(&self) -> &gltf::Document {
        &self.gltf.document
    }
}

/// One sentence per feature of `document` that the import leaves out.
fn left_out(document: &gltf::Document) -> Vec<String> {
    let mut warnings: Vec<String> = document
        .extensions_used()
        .filter(|e| !SUPPORTED_EXTENSIONS.contains(e))
        .map(|e| format!("extension `{e}` is not supported; what it adds is ignored"))
        .collect();
    if document.skins().next().is_some() {
        warnings.push(
            "skins (skeletal animation) are not supported yet; the meshes are shown in their bind pose"
                .to_owned(),
        );
    }
    if document
        .meshes()
        .any(|m| m.primitives().any(|p| p.morph_targets().next().is_some()))
    {
        warnings.push(
            "morph targets are not supported yet; the meshes are shown without them".to_owned(),
        );
    }
    let lines: Vec<String> = document
        .meshes()
        .filter(|m| !super::gltf_entities::has_triangles(m))
        .map(|m| m.index().to_string())
        .collect();
    if !lines.is_empty() {
        warnings.push(format!(
            "mesh(es) {} hold only points or lines, which Onyx does not draw yet; their nodes \
             get no mesh renderer",
            lines.join(", ")
        ));
    }
    warnings
}
