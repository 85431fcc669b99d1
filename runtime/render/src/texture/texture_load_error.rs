//! [`TextureLoadError`]: why an image file could not become a texture.

use std::path::PathBuf;

/// Why [`crate::Renderer::load_texture`] failed; names the file.
/// [`crate::Renderer::load_texture_or_fallback`] shows a magenta checker instead.
#[derive(Debug, thiserror::Error)]
pub enum TextureLoadError {
    /// The file could not be read.
    #[error("could not read texture `{}`: {source}; check that the file exists", path.display())]
    Read {
        /// The image file.
        path: PathBuf,
        /// I/O error.
        #[source]
        source: std::io::Error,
    },
    /// The file is not a PNG or JPEG image this build can decode, or it is corrupt.
    #[error("texture `{}` could not be decoded ({source}); save it as PNG or JPEG", path.display())]
    Decode {
        /// The image file.
        path: PathBuf,
        /// Decoder error.
        #[source]
        source: image::ImageError,
    },
    /// The image is larger than the adapter allows.
    #[error(
        "texture `{}` is {width}×{height} pixels, larger than this GPU's limit of {max}; scale it down",
        path.display()
    )]
    TooLarge {
        /// The image file.
        path: PathBuf,
        /// Image width in pixels.
        width: u32,
        /// Image height in pixels.
        height: u32,
        /// Largest side the adapter supports.
        max: u32,
    },
}
