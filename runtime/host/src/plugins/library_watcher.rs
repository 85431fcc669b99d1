//! [`LibraryWatcher`]: notices when a plugin library file has been rebuilt.

use std::collections::HashMap;
use std::hash::Hasher;
use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::fs::{FileWatcher, QUIET_PERIOD};

/// How long a library file must go without change events before it is checked for
/// completeness. Cargo writes a library in several pieces (and links it into place); loading
/// a half-written file would fail. An ELF file whose headers say it is whole is taken at
/// once; other files must also keep the same size over a second quiet period.
pub const RELOAD_QUIET_PERIOD: std::time::Duration = QUIET_PERIOD;

/// A content hash of a file, to ignore writes that change nothing (a `touch`, a no-op build).
pub fn content_hash(path: &Path) -> std::io::Result<u64> {
    let bytes = std::fs::read(path)?;
    let mut hasher = std::collections::hash_map::DefaultHasher::new();
    hasher.write(&bytes);
    Ok(hasher.finish())
}

#[derive(Debug)]
struct WatchedFile {
    hash: u64,
    dirty_since: Option<Instant>,
    len: Option<u64>,
}

/// Watches plugin library files (through their directories, as builds replace files) and
/// reports each file once its new content is complete and differs from what was loaded, with
/// the hash of that content.
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

    /// Starts watching `path`, whose current content hashes to `hash`.
    pub fn watch(&mut self, path: &Path, hash: u64) -> notify::Result<()> {
        let path = absolute(path);
        if self.files.contains_key(&path) {
            return Ok(());
        }
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        self.folders.watch_dir(&dir)?;
        self.files.insert(
            path,
            WatchedFile {
                hash,
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

    /// Files that changed and are now complete (quiet for [`RELOAD_QUIET_PERIOD`], same size
    /// twice, new content). Call it once per frame.
    pub fn poll(&mut self) -> Vec<(PathBuf, u64)> {
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
            if now.duration_since(since) < RELOAD_QUIET_PERIOD {
                continue;
            }
            let Ok(len) = std::fs::metadata(path).map(|m| m.len()) else {
                continue; // removed for now; a later event will mark it again
            };
            let complete = file.len == Some(len) || super::library_check::is_complete_elf(path);
            if !complete {
                file.len = Some(len);
                file.dirty_since = Some(now);
                continue;
            }
            file.dirty_since = None;
            match content_hash(path) {
                Ok(hash) if hash == file.hash => {
                    tracing::debug!(path = %path.display(), "plugin file rewritten with the same content; ignored");
                }
                Ok(hash) => {
                    file.hash = hash;
                    ready.push((path.clone(), hash));
                }
                Err(error) => {
                    tracing::warn!(path = %path.display(), "cannot read rebuilt plugin: {error}")
                }
            }
        }
        ready
    }

    /// Records that `path` now holds content hashing to `hash` (after a manual reload).
    pub fn set_hash(&mut self, path: &Path, hash: u64) {
        if let Some(file) = self.files.get_mut(&absolute(path)) {
            file.hash = hash;
        }
    }

    /// Whether `path` is watched.
    pub fn watches(&self, path: &Path) -> bool {
        self.files.contains_key(&absolute(path))
    }
}
