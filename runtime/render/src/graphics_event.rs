//! [`GraphicsEvent`]: something the GPU or the renderer reported that the host should see
//! (the successor of an OpenGL debug callback).

/// An event from the graphics device or renderer, queued for the host to drain with
/// [`crate::GpuContext::drain_events`] (also logged through `tracing` when it happens).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum GraphicsEvent {
    /// wgpu reported a validation error no error scope caught (a renderer bug or misuse).
    Validation {
        /// wgpu's description.
        description: String,
    },
    /// The device ran out of memory.
    OutOfMemory,
    /// An internal error in wgpu or the driver.
    Internal {
        /// wgpu's description.
        description: String,
    },
    /// The device was lost (driver reset, GPU removed, or destroyed). Rendering stops; the
    /// host may create a new renderer.
    DeviceLost {
        /// Why, as wgpu puts it.
        reason: String,
        /// Driver message.
        message: String,
    },
    /// A shader failed to compile; the last good pipeline stays in use.
    ShaderCompileFailed {
        /// Shader file name.
        shader: String,
        /// Compiler message.
        message: String,
    },
}

impl std::fmt::Display for GraphicsEvent {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            GraphicsEvent::Validation { description } => {
                write!(f, "GPU validation error: {description}")
            }
            GraphicsEvent::OutOfMemory => f.write_str("the GPU ran out of memory"),
            GraphicsEvent::Internal { description } => {
                write!(f, "internal GPU error: {description}")
            }
            GraphicsEvent::DeviceLost { reason, message } => {
                write!(f, "GPU device lost ({reason}): {message}")
            }
            GraphicsEvent::ShaderCompileFailed { shader, message } => {
                write!(
                    f,
                    "shader `{shader}` failed to compile, keeping the previous version: {message}"
                )
            }
        }
    }
}
