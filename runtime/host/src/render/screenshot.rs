//! Screenshots: why one was not taken, and saving one as a PNG.

use std::path::{Path, PathBuf};

use onyx_render::{ReadbackError, RenderError, RendererInitError};

/// Why a screenshot was not taken.
#[derive(Debug, thiserror::Error)]
pub enum ScreenshotError {
    /// No renderer could be created (no GPU and no CPU adapter).
    #[error("no renderer for the screenshot: {0}")]
    Init(#[from] RendererInitError),
    /// Drawing failed.
    #[error("could not render the screenshot: {0}")]
    Render(#[from] RenderError),
    /// Reading the image back failed.
    #[error("could not read the screenshot back: {0}")]
    Readback(#[from] ReadbackError),
    /// The image is larger than the GPU's largest texture: it cannot be drawn (it would come
    /// back empty).
    #[error(
        "a {width} × {height} screenshot is larger than this GPU's largest image \
         ({max} × {max} pixels); ask for a smaller --size"
    )]
    TooLarge {
        /// Width asked for, pixels.
        width: u32,
        /// Height asked for, pixels.
        height: u32,
        /// The GPU's limit on either side, pixels.
        max: u32,
    },
    /// Writing the file failed.
    #[error("could not write the screenshot to `{}`: {message}", .path.display())]
    Save {
        /// The file.
        path: PathBuf,
        /// Why.
        message: String,
    },
}

/// Saves `image` as a PNG at `path`, atomically.
pub fn save_png(image: &onyx_render::image::RgbaImage, path: &Path) -> Result<(), ScreenshotError> {
    let save_error = |message: String| ScreenshotError::Save {
        path: path.to_path_buf(),
        message,
    };
    let mut bytes = std::io::Cursor::new(Vec::new());
    image
        .write_to(&mut bytes, onyx_render::image::ImageFormat::Png)
        .map_err(|e| save_error(e.to_string()))?;
    crate::fs::write_atomically(path, bytes.get_ref()).map_err(|e| save_error(e.to_string()))
}
