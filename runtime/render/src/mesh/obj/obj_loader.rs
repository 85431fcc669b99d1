//! [`load_obj_source`]: an OBJ file, its material libraries and their texture references,
//! on the CPU.

use std::path::{Path, PathBuf};

use glam::Mat4;

use super::mtl_library::parse_mtl;
use super::obj_builder::build_parts;
use super::obj_document::parse_obj;
use crate::asset_io::{
    decode_text, read_asset_file, resolve_referenced_path, AssetReadError, AssetWarning,
    MAX_ASSET_FILE_BYTES,
};
use crate::mesh::import_settings::ImportSettings;
use crate::mesh::model_load_error::ModelLoadError;
use crate::mesh::model_source::{ModelSource, PartSource};
use crate::model_material::{ModelMaterial, UvTransform};

/// Reads an OBJ file and the MTL files it names into a [`ModelSource`] (images not decoded
/// yet). Fatal: an unreadable file, a statement that is not OBJ, no faces at all. Problems
/// that leave something to draw (a missing MTL) are listed in `problems`, oddities in
/// `warnings`.
pub(crate) fn load_obj_source(
    path: &Path,
    settings: &ImportSettings,
) -> Result<ModelSource, ModelLoadError> {
    let bytes =
        read_asset_file(path, MAX_ASSET_FILE_BYTES).map_err(|source| ModelLoadError::Read {
            path: path.to_owned(),
            source,
        })?;
    let mut warnings = Vec::new();
    let text = read_text(&bytes, path, &mut warnings);
    // The file's bytes and its text are each as large as the file: neither is needed once
    // the next stage has them (a 2M-triangle file held both through the whole build).
    drop(bytes);
    let mut doc = parse_obj(&text, path)?;
    drop(text);
    warnings.append(&mut doc.warnings);
    let folder = path.parent().unwrap_or(Path::new(""));

    let mut materials: Vec<ModelMaterial> = Vec::new();
    let mut failed: Vec<(PathBuf, usize, AssetReadError)> = Vec::new();
    for (written, line) in &doc.libraries {
        for name in library_names(folder, written) {
            let mtl = resolve_referenced_path(folder, &name);
            match read_asset_file(&mtl, MAX_ASSET_FILE_BYTES) {
                Ok(bytes) => {
                    let text = read_text(&bytes, &mtl, &mut warnings);
                    let (mut found, mut notes) = parse_mtl(&text, &mtl);
                    materials.append(&mut found);
                    warnings.append(&mut notes);
                }
                Err(error) => failed.push((mtl, *line, error)),
            }
        }
    }
    let find = |name: &str| materials.iter().find(|m| m.name == name);
    let unresolved: Vec<&str> = doc
        .parts
        .iter()
        .filter_map(|p| p.material.as_deref())
        .filter(|name| find(name).is_none())
        .collect();
    let mut problems = Vec::new();
    for (mtl, line, source) in failed {
        if unresolved.is_empty() {
            warnings.push(AssetWarning::new(
                path,
                Some(line),
                format!("material library `{}` was not loaded ({source}); no material the file uses is in it", mtl.display()),
            ));
        } else {
            problems.push(ModelLoadError::Mtl {
                obj: path.to_owned(),
                mtl,
                source,
            });
        }
    }
    let libraries_failed = !problems.is_empty();
    if !libraries_failed {
        for name in &unresolved {
            warnings.push(AssetWarning::new(
                path,
                None,
                format!("material `{name}` is not defined in the file's material libraries; the default material is used"),
            ));
        }
    }

    let uv_of = |key: usize| -> UvTransform {
        doc.parts[key]
            .material
            .as_deref()
            .and_then(find)
            .and_then(|m| m.base_color_texture.as_ref())
            .map_or(UvTransform::IDENTITY, |t| t.transform)
    };
    let built = build_parts(&doc, settings, uv_of, path, &mut warnings);
    if built.is_empty() {
        return Err(ModelLoadError::Empty {
            path: path.to_owned(),
        });
    }
    let parts = built
        .into_iter()
        .map(|part| {
            let key = &doc.parts[part.key];
            let material = key.material.as_deref().and_then(find).cloned();
            let missing = key.material.is_some() && material.is_none() && libraries_failed;
            PartSource {
                name: key.name.clone(),
                mesh: part.mesh,
                material: material.unwrap_or_else(|| ModelMaterial {
                    name: key.material.clone().unwrap_or_default(),
                    base_color: [0.8, 0.8, 0.8, 1.0],
                    metallic: 0.0,
                    roughness: 0.5,
                    ..ModelMaterial::default()
                }),
                material_missing: missing,
                transform: Mat4::IDENTITY,
            }
        })
        .collect::<Vec<_>>();
    let triangles: usize = parts.iter().map(|p| p.mesh.triangle_count()).sum();
    tracing::debug!(path = %path.display(), parts = parts.len(), triangles, "OBJ read");
    Ok(ModelSource::new(path.to_owned(), parts, problems, warnings))
}

/// Decodes a text file, warning when it was not UTF-8.
fn read_text(bytes: &[u8], path: &Path, warnings: &mut Vec<AssetWarning>) -> String {
    let (text, encoding) = decode_text(bytes);
    if encoding.is_unusual() {
        warnings.push(AssetWarning::new(
            path,
            None,
            format!("the file is not UTF-8; it was read as {}", encoding.name()),
        ));
    }
    text
}

/// The files an `mtllib` statement names: the whole line when it names one existing file
/// (a name with spaces), else each whitespace-separated name (`\ ` is a space inside one).
fn library_names(folder: &Path, written: &str) -> Vec<String> {
    let whole = written.replace("\\ ", " ");
    if resolve_referenced_path(folder, &whole).is_file() {
        return vec![whole];
    }
    let mut names = Vec::new();
    let mut current = String::new();
    let mut chars = written.chars().peekable();
    while let Some(c) = chars.next() {
        if c == '\\' && chars.peek() == Some(&' ') {
            current.push(' ');
            chars.next();
        } else if c.is_whitespace() {
            if !current.is_empty() {
                names.push(std::mem::take(&mut current));
            }
        } else {
            current.push(c);
        }
    }
    if !current.is_empty() {
        names.push(current);
    }
    names
}
