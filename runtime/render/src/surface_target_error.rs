//! [`SurfaceTargetError`]: why a window surface cannot be rendered to.

/// Why [`crate::SurfaceTarget::new`] failed.
#[derive(Debug, thiserror::Error)]
pub enum SurfaceTargetError {
    /// The adapter cannot present to this surface.
    #[error(
        "the graphics adapter `{adapter}` cannot present to this window; create the GpuContext \
         with this surface as its compatible surface"
    )]
    Unsupported {
        /// Adapter name.
        adapter: String,
    },
}
