//! [`ModelLoadError`]: why a model file (OBJ, its MTL or a texture) could not be loaded.

use std::path::PathBuf;

use crate::asset_io::AssetReadError;
use crate::texture::TextureLoadError;

/// Why [`crate::Renderer::load_model`] failed. Every variant names the file at fault, and
/// the line where the format has lines.
/// [`crate::Renderer::load_model_or_fallback`] turns these into visible placeholders.
#[derive(Debug, thiserror::Error)]
pub enum ModelLoadError {
    /// The model file could not be read (missing, unreadable, not a regular file, too large).
    #[error("model {source}")]
    Read {
        /// The model file.
        path: PathBuf,
        /// Why (names the file).
        #[source]
        source: AssetReadError,
    },
    /// A statement of the OBJ file is not OBJ.
    #[error("model `{}`, line {line}: {message}; fix the line or re-export the file as Wavefront OBJ", path.display())]
    ObjParse {
        /// The OBJ file.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// The file has no faces.
    #[error("model `{}` contains no faces; export faces, not only points or lines", path.display())]
    Empty {
        /// The model file.
        path: PathBuf,
    },
    /// A material library named by `mtllib` could not be read.
    #[error(
        "material library `{}` used by `{}` could not be loaded ({source}); put the .mtl file next \
         to the .obj or fix its `mtllib` line",
        mtl.display(),
        obj.display()
    )]
    Mtl {
        /// The OBJ file.
        obj: PathBuf,
        /// The MTL file it names.
        mtl: PathBuf,
        /// Why.
        #[source]
        source: AssetReadError,
    },
    /// A texture named by a material failed to load.
    #[error("material `{material}` of `{}`: {source}", obj.display())]
    Texture {
        /// The model file.
        obj: PathBuf,
        /// Material name.
        material: String,
        /// Texture error (names the texture file); boxed to keep this enum small.
        #[source]
        source: Box<TextureLoadError>,
    },
    /// The glTF file is malformed, or a buffer it needs is missing.
    #[error("glTF `{}`: {message}", path.display())]
    Gltf {
        /// The glTF file.
        path: PathBuf,
        /// What is wrong, as a sentence a user can act on.
        message: String,
    },
    /// The glTF file requires an extension Onyx does not implement.
    #[error(
        "glTF `{}` requires extension `{extension}`, which Onyx does not support; re-export it without it",
        path.display()
    )]
    RequiredExtension {
        /// The glTF file.
        path: PathBuf,
        /// The extension's name.
        extension: String,
    },
}
