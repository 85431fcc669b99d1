//! [`ShaderError`] (one shader failed) and [`ShaderReloadError`] (a reload had failures).

use std::path::PathBuf;

/// Why one shader could not be turned into a pipeline.
#[derive(Debug, thiserror::Error)]
pub enum ShaderError {
    /// The WGSL file could not be read.
    #[error("could not read shader file `{}`: {source}; check the shader folder", path.display())]
    Read {
        /// File that failed.
        path: PathBuf,
        /// I/O error.
        #[source]
        source: std::io::Error,
    },
    /// The WGSL did not compile (or the pipeline built from it was rejected).
    #[error("shader `{shader}` failed to compile; fix the WGSL and reload:\n{message}")]
    Compile {
        /// Shader file name.
        shader: String,
        /// Compiler / validation message, with the line it points at.
        message: String,
    },
}

/// [`crate::Renderer::reload_shaders`] found shaders that failed; every other shader was
/// reloaded, and each failed one keeps its last good version.
#[derive(Debug, thiserror::Error)]
#[error(
    "{} shader(s) failed to reload, the previous versions stay in use: {}",
    failures.len(),
    failures.iter().map(ToString::to_string).collect::<Vec<_>>().join("; ")
)]
pub struct ShaderReloadError {
    /// One error per failed shader.
    pub failures: Vec<ShaderError>,
}
