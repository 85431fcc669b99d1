//! [`LibraryWatcher`]: notices when a plugin library file has been rebuilt.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::fs::{FileWatcher, QUIET_PERIOD};

/// How long a changed library file that does not (yet) read as a complete ELF library must
/// go without change events, twice at the same size, before it is handed out anyway (to be
/// refused with a sentence if it is still incomplete). An ELF file whose headers say it is
/// whole is handed out at the first poll after its change: cargo links into place, and a
/// writer that writes in pieces leaves the file shorter than its headers until the end.
pub const RELOAD_QUIET_PERIOD: std::time::Duration = QUIET_PERIOD;

#[derive(Debug)]
struct WatchedFile {
    dirty_since: Option<Instant>,
    len: Option<u64>,
}

/// Watches plugin library files (through their directories, as builds replace files) and
/// reports each file once its new content is complete. Whether the content differs from what
/// was loaded is for the caller to tell (it reads the file anyway).
pub struct LibraryWatcher {
    folders: FileWatcher,
    files: HashMap<PathBuf, WatchedFile>,
}

impl std::fmt::Debug for LibraryWatcher {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LibraryWatcher")
            .field("files", &self.files.keys().collect::<Vec<_>>())
            .finish()
    }
}

fn absolute(path: &Path) -> PathBuf {
    std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf())
}

impl LibraryWatcher {
    /// A watcher watching nothing yet.
    pub fn new() -> notify::Result<Self> {
        Ok(Self {
            folders: FileWatcher::new()?,
            files: HashMap::new(),
        })
    }

    /// Starts watching `path`.
    pub fn watch(&mut self, path: &Path) -> notify::Result<()> {
        let path = absolute(path);
        if self.files.contains_key(&path) {
            return Ok(());
        }
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        self.folders.watch_dir(&dir)?;
        self.files.insert(
            path,
            WatchedFile {
                dirty_since: None,
                len: None,
            },
        );
        Ok(())
    }

    /// Stops watching `path`.
    pub fn unwatch(&mut self, path: &Path) {
        let path = absolute(path);
        if self.files.remove(&path).is_none() {
            return;
        }
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        self.folders.unwatch_dir(&dir);
    }

    /// Files that changed and are now complete: an ELF library whose headers say so at once,
    /// another file once it kept its size over [`RELOAD_QUIET_PERIOD`]. Call it once per frame.
    pub fn poll(&mut self) -> Vec<PathBuf> {
        let now = Instant::now();
        let files = &mut self.files;
        self.folders.drain(|at, path| {
            if let Some(file) = files.get_mut(path) {
                file.dirty_since = Some(file.dirty_since.map_or(at, |d| d.max(at)));
                file.len = None;
            }
        });
        let mut ready = Vec::new();
        for (path, file) in &mut self.files {
            let Some(since) = file.dirty_since else {
                continue;
            };
            if super::library_check::is_complete_elf(path) {
                file.dirty_since = None;
                ready.push(path.clone());
                continue;
            }
            if now.duration_since(since) < RELOAD_QUIET_PERIOD {
                continue;
            }
            let Ok(len) = std::fs::metadata(path).map(|m| m.len()) else {
                continue; // removed for now; a later event will mark it again
            };
            if file.len == Some(len) {
                file.dirty_since = None;
                ready.push(path.clone());
            } else {
                file.len = Some(len);
                file.dirty_since = Some(now);
            }
        }
        ready
    }

    /// Forgets changes seen so far to `path` (it was just loaded by other means).
    pub fn settle(&mut self, path: &Path) {
        if let Some(file) = self.files.get_mut(&absolute(path)) {
            file.dirty_since = None;
            file.len = None;
        }
    }

    /// Whether `path` is watched.
    pub fn watches(&self, path: &Path) -> bool {
        self.files.contains_key(&absolute(path))
    }
}
