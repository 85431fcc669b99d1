//! [`GraphicsEvent`]: events whose source is the renderer.

/// Something went wrong in rendering. The host keeps running; rendering goes on with a
/// fallback where it can.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum GraphicsEvent {
    /// The GPU or its driver reported an error (validation, out of memory, shader).
    Gpu {
        /// The error, as a sentence.
        message: String,
    },
    /// The GPU device was lost; nothing more is drawn.
    DeviceLost {
        /// Why.
        message: String,
    },
    /// A model, material or texture file could not be loaded; a fallback is drawn instead.
    AssetFailed {
        /// The file asked for.
        path: String,
        /// What is wrong with it (names the file at fault).
        message: String,
    },
}
