//! The window: winit 0.30.
//!
//! - `windowed_runner.rs`: [`run_windowed`], the event loop driving a [`Host`](crate::Host).
//! - `winit_input.rs`: winit input → Onyx input events.
//! - `window_gui.rs`: [`WindowGui`], egui-winit for plugin GUIs (input, cursor, clipboard).
//! - `window_error.rs`: [`WindowError`].

mod window_error;
mod window_gui;
mod windowed_runner;
pub mod winit_input;

pub use window_error::WindowError;
pub use window_gui::WindowGui;
pub use windowed_runner::{run_windowed, WindowOptions, WindowedSummary};
