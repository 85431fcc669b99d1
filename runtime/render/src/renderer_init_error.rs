//! [`RendererInitError`]: why a [`crate::Renderer`] could not be created.

use crate::gpu_init_error::GpuInitError;
use crate::pipeline::ShaderError;

/// Why [`crate::Renderer::new`] / [`crate::Renderer::new_headless`] failed.
#[derive(Debug, thiserror::Error)]
pub enum RendererInitError {
    /// No graphics device (see [`GpuInitError`]); the host can run without rendering.
    #[error(transparent)]
    Gpu(#[from] GpuInitError),
    /// A built-in (embedded) shader failed to compile on this device: a renderer bug or a
    /// driver problem.
    #[error("a built-in shader does not compile on this device: {0}")]
    Shader(#[from] ShaderError),
}
