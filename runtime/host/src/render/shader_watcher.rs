//! [`ShaderWatcher`]: notices edits in the shader folder; [`shader_dir`]: where it is.

use std::path::Path;
use std::time::Instant;

use crate::fs::{FileWatcher, QUIET_PERIOD};

/// Watches the WGSL folder; [`ShaderWatcher::poll`] says when an edit has settled (no change
/// for [`QUIET_PERIOD`]), so an editor's save-in-pieces is recompiled once.
#[derive(Debug)]
pub struct ShaderWatcher {
    files: FileWatcher,
    dirty_since: Option<Instant>,
}

impl ShaderWatcher {
    /// Watches `dir` (not recursively).
    pub fn new(dir: &Path) -> notify::Result<Self> {
        let mut files = FileWatcher::new()?;
        files.watch_dir(dir)?;
        Ok(Self {
            files,
            dirty_since: None,
        })
    }

    /// Whether shaders changed and the folder has been quiet since.
    pub fn poll(&mut self) -> bool {
        let now = Instant::now();
        let dirty_since = &mut self.dirty_since;
        self.files.drain(|at, path| {
            if path.extension().is_some_and(|e| e == "wgsl") {
                *dirty_since = Some(dirty_since.map_or(at, |d| d.max(at)));
            }
        });
        match self.dirty_since {
            Some(since) if now.duration_since(since) >= QUIET_PERIOD => {
                self.dirty_since = None;
                true
            }
            _ => false,
        }
    }
}

/// The `shaders/` folder of a source checkout, when the binary runs from one (so shaders can
/// be edited and reloaded); otherwise the copies embedded in the binary are used.
pub fn shader_dir() -> Option<std::path::PathBuf> {
    if let Some(dir) = std::env::var_os("ONYX_SHADER_DIR") {
        return Some(dir.into());
    }
    let dev = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shaders");
    (cfg!(debug_assertions) && dev.is_dir()).then_some(dev)
}
