//! OBJ + MTL loading through `tobj`: triangulated, single-indexed, one part per material,
//! normals (smooth) and texture coordinates (box projection) generated when the file has none.

use std::cell::RefCell;
use std::io::BufReader;
use std::path::{Path, PathBuf};

use super::mesh_data::MeshData;
use super::model_load_error::ModelLoadError;
use super::vertex::Vertex;

/// Material of an OBJ part, as read from the MTL file.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ObjMaterial {
    pub(crate) name: String,
    /// Diffuse colour (`Kd`), linear RGB; white when absent.
    pub(crate) diffuse: [f32; 3],
    /// Diffuse texture (`map_Kd`), resolved against the MTL file's folder.
    pub(crate) texture: Option<PathBuf>,
}

/// One mesh of an OBJ file.
#[derive(Clone, Debug)]
pub(crate) struct ObjPart {
    pub(crate) name: String,
    pub(crate) mesh: MeshData,
    /// `None` when the part names no material or the MTL failed.
    pub(crate) material: Option<ObjMaterial>,
}

/// What an OBJ file held, plus the non-fatal problems met (a missing MTL).
#[derive(Debug)]
pub(crate) struct ObjModel {
    pub(crate) parts: Vec<ObjPart>,
    pub(crate) problems: Vec<ModelLoadError>,
}

/// Reads an OBJ file and its MTL. Fatal problems (unreadable or malformed OBJ, no
/// triangles) are errors; a missing or malformed MTL is listed in `problems`.
pub(crate) fn load_obj(path: &Path) -> Result<ObjModel, ModelLoadError> {
    let file = std::fs::File::open(path).map_err(|source| ModelLoadError::ObjRead {
        path: path.to_owned(),
        source,
    })?;
    let mut reader = BufReader::new(file);
    let folder = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let mtl_path: RefCell<Option<PathBuf>> = RefCell::new(None);
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    let (models, materials) = tobj::load_obj_buf(&mut reader, &options, |mtl| {
        let full = folder.join(mtl);
        *mtl_path.borrow_mut() = Some(full.clone());
        tobj::load_mtl(full)
    })
    .map_err(|source| match source {
        tobj::LoadError::ReadError | tobj::LoadError::OpenFileFailed => ModelLoadError::ObjRead {
            path: path.to_owned(),
            source: std::io::Error::new(std::io::ErrorKind::InvalidData, source.to_string()),
        },
        source => ModelLoadError::ObjParse {
            path: path.to_owned(),
            source,
        },
    })?;

    let mut problems = Vec::new();
    let mtl_folder = mtl_path
        .borrow()
        .as_ref()
        .and_then(|p| p.parent().map(Path::to_path_buf))
        .unwrap_or(folder);
    let materials: Vec<ObjMaterial> = match materials {
        Ok(materials) => materials
            .into_iter()
            .map(|m| ObjMaterial {
                diffuse: m.diffuse.unwrap_or([1.0; 3]),
                texture: m
                    .diffuse_texture
                    .as_deref()
                    .map(|t| mtl_folder.join(t.trim())),
                name: m.name,
            })
            .collect(),
        Err(source) => {
            if let Some(mtl) = mtl_path.borrow().clone() {
                problems.push(ModelLoadError::Mtl {
                    obj: path.to_owned(),
                    mtl,
                    source,
                });
            }
            Vec::new()
        }
    };

    let parts: Vec<ObjPart> = models
        .into_iter()
        .filter_map(|model| {
            let material = model
                .mesh
                .material_id
                .and_then(|id| materials.get(id).cloned());
            let mesh = convert_mesh(&model.mesh)?;
            Some(ObjPart {
                name: model.name,
                mesh,
                material,
            })
        })
        .collect();
    if parts.is_empty() {
        return Err(ModelLoadError::Empty {
            path: path.to_owned(),
        });
    }
    let triangles: usize = parts.iter().map(|p| p.mesh.triangle_count()).sum();
    tracing::debug!(path = %path.display(), parts = parts.len(), triangles, "OBJ loaded");
    Ok(ObjModel { parts, problems })
}

/// tobj mesh → [`MeshData`]; `None` when it has no valid triangle.
fn convert_mesh(mesh: &tobj::Mesh) -> Option<MeshData> {
    let count = mesh.positions.len() / 3;
    let has_normals = mesh.normals.len() == count * 3;
    let has_uvs = mesh.texcoords.len() == count * 2;
    let vertices = (0..count)
        .map(|i| Vertex {
            position: [
                mesh.positions[3 * i],
                mesh.positions[3 * i + 1],
                mesh.positions[3 * i + 2],
            ],
            normal: if has_normals {
                [
                    mesh.normals[3 * i],
                    mesh.normals[3 * i + 1],
                    mesh.normals[3 * i + 2],
                ]
            } else {
                [0.0, 1.0, 0.0]
            },
            // OBJ puts v = 0 at the bottom of the image; textures here start at the top.
            uv: if has_uvs {
                [mesh.texcoords[2 * i], 1.0 - mesh.texcoords[2 * i + 1]]
            } else {
                [0.0, 0.0]
            },
        })
        .collect();
    let mut data = MeshData {
        vertices,
        indices: mesh.indices.clone(),
    };
    data.indices.truncate(data.indices.len() / 3 * 3);
    if !data.is_valid() {
        return None;
    }
    if !has_normals {
        data.compute_smooth_normals();
    }
    if !has_uvs {
        data.compute_box_uvs();
    }
    Some(data)
}

/// The geometry of an OBJ file on the CPU, all parts merged into one triangle list (for
/// collision shapes; no GPU needed). Materials are ignored.
///
/// # Errors
/// [`ModelLoadError`] naming the file when it cannot be read, is malformed or has no
/// triangles.
pub fn load_obj_geometry(path: &Path) -> Result<MeshData, ModelLoadError> {
    let model = load_obj(path)?;
    let mut merged = MeshData::default();
    for part in model.parts {
        let base = merged.vertices.len() as u32;
        merged.vertices.extend(part.mesh.vertices);
        merged
            .indices
            .extend(part.mesh.indices.into_iter().map(|i| i + base));
    }
    Ok(merged)
}
