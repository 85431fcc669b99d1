//! [`ReadbackError`]: why an offscreen image could not be read back.

/// Why [`crate::OffscreenTarget::read_image`] or a [`crate::SurfaceTarget`] screenshot failed.
#[derive(Debug, thiserror::Error)]
pub enum ReadbackError {
    /// Mapping the staging buffer failed (device lost or out of memory).
    #[error("could not map the readback buffer ({0}); the GPU device may have been lost")]
    Map(#[from] wgpu::BufferAsyncError),
    /// Waiting for the GPU failed.
    #[error("waiting for the GPU failed ({0}); the GPU device may have been lost")]
    Poll(#[from] wgpu::PollError),
    /// The mapped range could not be accessed.
    #[error("could not access the mapped readback buffer ({0})")]
    MappedRange(#[from] wgpu::MapRangeError),
    /// The texture was not created with `COPY_SRC` (a surface that does not offer it).
    #[error("this texture cannot be copied (no COPY_SRC usage); the window surface does not support screenshots")]
    NotCopyable,
    /// Only 8-bit RGBA / BGRA textures can be read back.
    #[error("textures of format {format:?} cannot be read back; only 8-bit RGBA / BGRA")]
    UnsupportedFormat {
        /// The texture's format.
        format: wgpu::TextureFormat,
    },
    /// The map callback never ran.
    #[error("the GPU never answered the readback request; the device may have been lost")]
    NoAnswer,
}
