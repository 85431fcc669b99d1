//! Rendering the world offscreen into an image, and saving it as a PNG.

use std::path::{Path, PathBuf};

use onyx_render::{OffscreenTarget, ReadbackError, RenderError, RendererInitError};

use super::RenderSystem;
use crate::world::HostState;

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
    /// Writing the file failed.
    #[error("could not write the screenshot to `{}`: {message}", .path.display())]
    Save {
        /// The file.
        path: PathBuf,
        /// Why.
        message: String,
    },
}

/// Draws the world into a `width` × `height` offscreen image.
pub fn render_image(
    system: &mut RenderSystem,
    state: &mut HostState,
    width: u32,
    height: u32,
) -> Result<onyx_render::image::RgbaImage, ScreenshotError> {
    let mut target = OffscreenTarget::new(system.renderer().gpu(), width.max(1), height.max(1));
    system.draw(state, &mut target)?;
    Ok(target.read_image(system.renderer().gpu())?)
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
    crate::scene::write_atomically(path, bytes.get_ref()).map_err(|e| save_error(e.to_string()))
}
