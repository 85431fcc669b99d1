//! [`RenderError`]: why a frame could not be drawn.

/// Why [`crate::Renderer::render`] drew nothing. Minimised windows and timeouts are not
/// errors: the frame is skipped and [`crate::RenderStats::skipped`] is set.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// The window surface is gone (window closed or driver reset).
    #[error("the window surface was lost; create a new surface and SurfaceTarget for the window")]
    SurfaceLost,
    /// Acquiring the surface texture failed validation.
    #[error("the window surface could not provide a frame (validation error); see the drained GraphicsEvents")]
    SurfaceValidation,
}
