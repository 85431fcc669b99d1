//! [`WindowEvent`]: events whose source is the window.

/// Something happened to the window.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum WindowEvent {
    /// The drawable area changed size, in physical pixels (0 × 0 when minimised).
    Resized {
        /// New width in pixels.
        width: u32,
        /// New height in pixels.
        height: u32,
    },
    /// The window gained (`true`) or lost (`false`) keyboard focus.
    Focused(bool),
    /// The user asked to close the window; the host quits after this frame unless a plugin
    /// keeps it open with [`Ctx::prevent_close`](crate::Ctx::prevent_close).
    CloseRequested,
}
