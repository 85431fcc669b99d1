//! Files: writing them safely and noticing when they change. Used by scenes, dumps and
//! screenshots (atomic writes) and by shader and plugin hot reload (watching).
//!
//! - `atomic_write.rs`: [`write_atomically`], a crash never leaves half a file.
//! - `file_watcher.rs`: [`FileWatcher`], change events for watched folders, time-stamped.

mod atomic_write;
mod file_watcher;

pub use atomic_write::write_atomically;
pub use file_watcher::{FileWatcher, QUIET_PERIOD};
