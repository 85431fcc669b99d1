//! [`GltfFile`]: a glTF file read once — its document, buffers and images' encoded bytes —
//! with the images it decodes kept, so every mesh taken from it (`file.glb#mesh/N`) shares one
//! parse and one decode of each image.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, PoisonError};

use super::gltf_buffers::{image_bytes, load_buffers};
use crate::asset_io::{read_asset_file, MAX_ASSET_FILE_BYTES};
use crate::mesh::model_load_error::ModelLoadError;
use crate::model_material::ImageSource;
use crate::texture::{decode_texture, decode_texture_bytes, TextureLoadError, TextureSource};

/// Extensions whose data Onyx reads.
pub(crate) const SUPPORTED_EXTENSIONS: [&str; 4] = [
    "KHR_lights_punctual",
    "KHR_texture_transform",
    "KHR_materials_emissive_strength",
    "KHR_materials_unlit",
];

/// One decoded image, decoded by the first mesh that needs it (the others wait for it).
type DecodedSlot = Arc<Mutex<Option<Arc<TextureSource>>>>;

/// A glTF or GLB file read and validated, with every buffer loaded.
pub(crate) struct GltfFile {
    /// The file.
    pub(crate) path: PathBuf,
    /// The validated document: every index it holds names something that exists.
    pub(crate) document: gltf::Document,
    /// Every buffer, in index order.
    pub(crate) buffers: Vec<Vec<u8>>,
    /// Encoded bytes of each image stored in the file (buffer view or `data:` URI), by
    /// index; an error sentence for one that cannot be had. `None` for images in files.
    embedded: Vec<Option<Result<Vec<u8>, String>>>,
    /// Images decoded so far, by source.
    decoded: Mutex<HashMap<ImageSource, DecodedSlot>>,
}

impl std::fmt::Debug for GltfFile {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GltfFile")
            .field("path", &self.path)
            .field("buffers", &self.buffers.len())
            .finish_non_exhaustive()
    }
}

impl GltfFile {
    /// Reads the file at `path` (regular files only): an extension it requires that Onyx
    /// lacks is an error; so is a document the crate does not validate or a buffer that
    /// cannot be loaded. Run it behind [`super::catch_gltf_panics`].
    pub(crate) fn read(path: &Path) -> Result<Self, ModelLoadError> {
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
        let gltf = gltf::Gltf::from_slice(body).map_err(invalid)?;
        let folder = path.parent().unwrap_or(Path::new("")).to_owned();
        let buffers =
            load_buffers(&gltf.document, gltf.blob.as_deref(), &folder).map_err(gltf_error)?;
        let embedded = gltf
            .document
            .images()
            .map(|image| match image.source() {
                gltf::image::Source::Uri { uri, .. } if !uri.starts_with("data:") => None,
                _ => Some(image_bytes(&image, &buffers, &folder)),
            })
            .collect();
        Ok(Self {
            path: path.to_owned(),
            document: gltf.document,
            buffers,
            embedded,
            decoded: Mutex::new(HashMap::new()),
        })
    }

    /// The image `source` names (one inside this file, or an image file it points at),
    /// decoded at most `max_side` pixels a side: decoded once, shared after.
    pub(crate) fn decoded_image(
        &self,
        source: &ImageSource,
        max_side: u32,
    ) -> Result<Arc<TextureSource>, TextureLoadError> {
        let slot = self
            .decoded
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .entry(source.clone())
            .or_default()
            .clone();
        let mut slot = slot.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(done) = &*slot {
            return Ok(done.clone());
        }
        let decoded = match source {
            ImageSource::Embedded { index, .. } => {
                let name = PathBuf::from(source.to_string());
                match self.embedded.get(*index).and_then(Option::as_ref) {
                    Some(Ok(bytes)) => decode_texture_bytes(bytes, &name, max_side)?,
                    Some(Err(message)) => {
                        return Err(TextureLoadError::Unsupported {
                            path: name,
                            format: format!("unreadable ({message})"),
                        })
                    }
                    None => {
                        return Err(TextureLoadError::Unsupported {
                            path: name,
                            format: "an image the file does not hold".to_owned(),
                        })
                    }
                }
            }
            ImageSource::File(_) => decode_texture(source, max_side)?,
        };
        let decoded = Arc::new(decoded);
        *slot = Some(decoded.clone());
        Ok(decoded)
    }
}

/// Files being read for models (`file.glb#mesh/N`), shared while any load holds a
/// [`GltfFileLease`] on them: a scene drawing twenty meshes of one file parses it once, and
/// the file is let go once its last load is done. Cloning shares the same set.
#[derive(Clone, Debug, Default)]
pub struct GltfFiles {
    open: Arc<Mutex<HashMap<PathBuf, Lent>>>,
}

#[derive(Debug)]
struct Lent {
    file: Arc<Mutex<Option<Arc<GltfFile>>>>,
    leases: usize,
}

impl GltfFiles {
    /// A hold on the file at `path` (read on first use, by [`GltfFileLease`]'s holder).
    #[must_use]
    pub fn lease(&self, path: &Path) -> GltfFileLease {
        let mut open = self.open.lock().unwrap_or_else(PoisonError::into_inner);
        let lent = open.entry(path.to_owned()).or_insert_with(|| Lent {
            file: Arc::default(),
            leases: 0,
        });
        lent.leases += 1;
        GltfFileLease {
            files: self.clone(),
            path: path.to_owned(),
            file: lent.file.clone(),
        }
    }

    /// Number of files held now.
    #[must_use]
    pub fn held(&self) -> usize {
        self.open
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .len()
    }
}

/// One load's hold on a glTF file in [`GltfFiles`]; the file is read by the first holder
/// that asks for it and dropped from the set with the last lease.
#[derive(Debug)]
pub struct GltfFileLease {
    files: GltfFiles,
    path: PathBuf,
    file: Arc<Mutex<Option<Arc<GltfFile>>>>,
}

impl GltfFileLease {
    /// The file the lease is on.
    #[must_use]
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The file, read now if no holder has read it yet (a failed read is not kept: the
    /// next holder tries again and gets its own error).
    pub(crate) fn file(&self) -> Result<Arc<GltfFile>, ModelLoadError> {
        let mut file = self.file.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(read) = &*file {
            return Ok(read.clone());
        }
        let read = Arc::new(super::catch_gltf_panics(&self.path, || {
            GltfFile::read(&self.path)
        })?);
        *file = Some(read.clone());
        Ok(read)
    }
}

impl Drop for GltfFileLease {
    fn drop(&mut self) {
        let mut open = self
            .files
            .open
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        if let Some(lent) = open.get_mut(&self.path) {
            lent.leases -= 1;
            if lent.leases == 0 {
                open.remove(&self.path);
            }
        }
    }
}
