//! For hosts, not plugins: open plugin libraries, call plugins, and serve [`Ctx`](crate::Ctx)
//! by implementing [`HostServices`] — all in plain Rust; the ABI stays inside this crate.
//!
//! - `plugin_library.rs`: [`PluginLibrary`], open + version/layout check.
//! - `plugin_instance.rs`: [`PluginInstance`], the lifecycle calls.
//! - `host_services.rs`: [`HostServices`], what the host implements.
//! - `library_error.rs`, `call_error.rs`: what can go wrong.
//! - `blob.rs`, `builtin_value.rs`: component values as the host stores them.

mod blob;
mod builtin_value;
mod call_error;
mod host_services;
mod library_error;
mod plugin_instance;
mod plugin_library;

pub use crate::__ffi::BuiltinId;
pub use blob::Blob;
pub use builtin_value::BuiltinValue;
pub use call_error::CallError;
pub use host_services::{HostServices, PhysicsCommand, PluginRequest};
pub use library_error::LibraryError;
pub use plugin_instance::PluginInstance;
pub use plugin_library::PluginLibrary;

/// The onyx-plugin-api version this host speaks (plugins must match major and, while 0.x,
/// minor).
pub const API_VERSION: &str = env!("CARGO_PKG_VERSION");
