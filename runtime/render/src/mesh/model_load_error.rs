//! [`ModelLoadError`]: why a model file (OBJ, its MTL or a texture) could not be loaded.

use std::path::PathBuf;

use crate::texture::TextureLoadError;

/// Why [`crate::Renderer::load_model`] failed. Every variant names the file at fault.
/// [`crate::Renderer::load_model_or_fallback`] turns these into visible placeholders.
#[derive(Debug, thiserror::Error)]
pub enum ModelLoadError {
    /// The OBJ file could not be opened or read.
    #[error("could not read model `{}`: {source}; check that the file exists and is readable", path.display())]
    ObjRead {
        /// The OBJ file.
        path: PathBuf,
        /// I/O error.
        #[source]
        source: std::io::Error,
    },
    /// The OBJ file is not valid OBJ.
    #[error("model `{}` is not a valid OBJ file ({source}); re-export it as Wavefront OBJ", path.display())]
    ObjParse {
        /// The OBJ file.
        path: PathBuf,
        /// Parser error.
        #[source]
        source: tobj::LoadError,
    },
    /// The OBJ file has no triangles.
    #[error("model `{}` contains no triangles; export faces, not only points or lines", path.display())]
    Empty {
        /// The OBJ file.
        path: PathBuf,
    },
    /// The material library named by `mtllib` is missing or malformed.
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
        /// Parser error.
        #[source]
        source: tobj::LoadError,
    },
    /// A texture named by a material failed to load.
    #[error("material `{material}` of `{}`: {source}", obj.display())]
    Texture {
        /// The OBJ file.
        obj: PathBuf,
        /// Material name.
        material: String,
        /// Texture error (names the texture file); boxed to keep this enum small.
        #[source]
        source: Box<TextureLoadError>,
    },
}
