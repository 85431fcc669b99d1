//! For hosts, not plugins: open plugin libraries, call plugins, and serve [`Ctx`](crate::Ctx)
//! by implementing [`HostServices`] — all in plain Rust; the ABI stays inside this crate.
//!
//! - `plugin_library.rs`: [`PluginLibrary`], open + version/layout check.
//! - `plugin_instance.rs`: [`PluginInstance`], the lifecycle calls.
//! - `host_services.rs`: [`HostServices`], what the host implements.
//! - `tool_services.rs`: [`ToolServices`], the tool half (editor services), all defaulted;
//!   `play_command.rs`: [`PlayCommand`].
//! - `gui_input.rs`, `gui_output.rs`: one GUI frame of a plugin, in and out, as egui types.
//! - `library_error.rs`, `call_error.rs`: what can go wrong.
//! - `blob.rs`: a plugin component as the host stores it.

mod blob;
mod call_error;
mod gui_input;
mod gui_output;
mod host_services;
mod library_error;
mod play_command;
mod plugin_instance;
mod plugin_library;
mod tool_services;

pub use blob::Blob;
pub use call_error::CallError;
pub use gui_input::GuiInput;
pub use gui_output::GuiOutput;
pub use host_services::{HostServices, PhysicsCommand, PluginRequest};
pub use library_error::LibraryError;
pub use play_command::PlayCommand;
pub use plugin_instance::PluginInstance;
pub use plugin_library::PluginLibrary;
pub use tool_services::ToolServices;

/// The onyx-plugin-api version this host speaks (plugins must match major and, while 0.x,
/// minor).
pub const API_VERSION: &str = env!("CARGO_PKG_VERSION");
