//! [`GpuInitError`]: why no graphics device could be opened.

/// Why [`crate::GpuContext`] could not be created. The host can keep running without
/// rendering.
#[derive(Debug, thiserror::Error)]
pub enum GpuInitError {
    /// No adapter at all, not even a CPU one.
    #[error(
        "no graphics adapter found ({reason}); install a GPU driver, or Mesa's lavapipe \
         (Debian: mesa-vulkan-drivers) to render on the CPU, or run without rendering"
    )]
    NoAdapter {
        /// wgpu's reason.
        reason: String,
    },
    /// `WGPU_ADAPTER_NAME` names an adapter that is not present.
    #[error(
        "WGPU_ADAPTER_NAME is `{requested}` but no adapter matches; available: {available}. \
         Unset it or pick one of those"
    )]
    NamedAdapterMissing {
        /// The requested name.
        requested: String,
        /// Names of the adapters found.
        available: String,
    },
    /// The adapter refused to open a device.
    #[error("the adapter `{adapter}` could not open a device: {source}")]
    RequestDevice {
        /// Adapter name.
        adapter: String,
        /// wgpu's error.
        #[source]
        source: wgpu::RequestDeviceError,
    },
}
