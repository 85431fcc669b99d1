//! [`TextureLoadError`]: why an image file could not become a texture.

use std::path::PathBuf;

use crate::asset_io::AssetReadError;

/// Why [`crate::Renderer::load_texture`] failed; names the file.
/// [`crate::Renderer::load_texture_or_fallback`] shows the missing-texture placeholder instead.
#[derive(Debug, thiserror::Error)]
pub enum TextureLoadError {
    /// The file could not be read (missing, unreadable, not a regular file, too large).
    #[error("texture {source}")]
    Read {
        /// The image file.
        path: PathBuf,
        /// Why (names the file).
        #[source]
        source: AssetReadError,
    },
    /// The file is a PNG or JPEG, but corrupt or truncated.
    #[error("texture `{}` is damaged and could not be decoded ({source}); re-export it", path.display())]
    Decode {
        /// The image file.
        path: PathBuf,
        /// Decoder error.
        #[source]
        source: image::ImageError,
    },
    /// The file is not an image format this build decodes.
    #[error("texture `{}` is {format}; Onyx reads PNG and JPEG: convert it to one of those", path.display())]
    Unsupported {
        /// The image file.
        path: PathBuf,
        /// What it is, as a phrase ("a Tga image").
        format: String,
    },
    /// The image has more pixels than Onyx decodes (seen in its header, before decoding).
    #[error(
        "texture `{}` is {width}×{height} pixels, more than the {max_pixels} pixels Onyx decodes; scale it down",
        path.display()
    )]
    TooLarge {
        /// The image file.
        path: PathBuf,
        /// Image width in pixels.
        width: u32,
        /// Image height in pixels.
        height: u32,
        /// Largest number of pixels decoded.
        max_pixels: u64,
    },
}

impl TextureLoadError {
    /// The image file.
    #[must_use]
    pub fn path(&self) -> &std::path::Path {
        match self {
            TextureLoadError::Read { path, .. }
            | TextureLoadError::Decode { path, .. }
            | TextureLoadError::Unsupported { path, .. }
            | TextureLoadError::TooLarge { path, .. } => path,
        }
    }
}
