//! [`WindowError`]: why the window could not run.

/// The windowed runner could not start or failed.
#[derive(Debug, thiserror::Error)]
pub enum WindowError {
    /// No event loop: usually no display to connect to.
    #[error(
        "could not open a window: {0}. Is a display available (DISPLAY or WAYLAND_DISPLAY)? \
         Run with --headless, or under `xvfb-run -a`"
    )]
    EventLoop(#[source] winit::error::EventLoopError),
    /// The window itself could not be created.
    #[error("could not create the window: {0}")]
    CreateWindow(#[source] winit::error::OsError),
}
