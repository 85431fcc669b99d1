//! Plugins: finding, loading, and calling them.
//!
//! - `plugin_search.rs`: [`PluginSearchPath`], NAME → library file.
//! - `plugin_loader.rs`: [`open_library`], fresh-copy loading (one mapping: hash, check, copy),
//!   timed in [`LoadTimings`].
//! - `image_unload.rs`: [`ImageFate`], an old build's image handed back to the system loader
//!   once nothing from it can run (and how the host knows).
//! - `library_check.rs`: refuses library files that are half-written or damaged where the
//!   system loader would crash on them, before they are mapped.
//! - `plugin_load_error.rs`: [`PluginLoadError`], one sentence per failure.
//! - `plugin_slot.rs`: [`PluginSlot`], a loaded plugin and its fault handling.
//! - `plugin_status.rs`: running or faulted (in which [`Stage`], `crate::stage`).
//! - `library_watcher.rs`: [`LibraryWatcher`], notices rebuilt libraries (hot reload).
//! - `reload_error.rs`: [`ReloadError`], why a new build did not replace the old one.
//! - `reload_report.rs`: [`ReloadReport`], one swap stage by stage.
//! - `reload_gate.rs`: [`ReloadGate`], holds automatic reloads during builds, then swaps a
//!   whole round in one frame.

mod image_unload;
pub mod library_check;
pub mod library_watcher;
mod plugin_load_error;
mod plugin_loader;
pub mod plugin_search;
mod plugin_slot;
mod plugin_status;
mod reload_error;
mod reload_gate;
mod reload_report;

pub use crate::stage::Stage;
pub use image_unload::ImageFate;
pub(crate) use image_unload::{unload_image, RetiredImage};
pub use library_watcher::LibraryWatcher;
pub use plugin_load_error::PluginLoadError;
pub use plugin_loader::{content_hash, open_library, LoadTimings, OpenedLibrary};
pub(crate) use plugin_loader::{open_library_bytes, read_library, LibraryBytes};
pub use plugin_search::{PluginSearchPath, PLUGIN_PATH_VAR};
pub use plugin_slot::{PluginOrigin, PluginSlot};
pub use plugin_status::PluginStatus;
pub use reload_error::ReloadError;
pub use reload_gate::ReloadGate;
pub use reload_report::ReloadReport;
