//! [`ShaderWatcher`]: notices edits in the shader folder.

use std::path::Path;
use std::sync::mpsc::{channel, Receiver};
use std::time::Instant;

use notify::{RecursiveMode, Watcher};

use crate::plugins::library_watcher::RELOAD_QUIET_PERIOD;

/// Watches the WGSL folder; [`ShaderWatcher::poll`] says when an edit has settled (no change
/// for [`RELOAD_QUIET_PERIOD`]), so an editor's save-in-pieces is recompiled once.
pub struct ShaderWatcher {
    _watcher: notify::RecommendedWatcher,
    /// Events, stamped with when they happened (not when they were read).
    events: Receiver<(Instant, notify::Result<notify::Event>)>,
    dirty_since: Option<Instant>,
}

impl std::fmt::Debug for ShaderWatcher {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ShaderWatcher").finish_non_exhaustive()
    }
}

impl ShaderWatcher {
    /// Watches `dir` (not recursively).
    pub fn new(dir: &Path) -> notify::Result<Self> {
        let (tx, events) = channel();
        let mut watcher = notify::recommended_watcher(move |event| {
            let _ = tx.send((Instant::now(), event));
        })?;
        watcher.watch(dir, RecursiveMode::NonRecursive)?;
        Ok(Self {
            _watcher: watcher,
            events,
            dirty_since: None,
        })
    }

    /// Whether shaders changed and the folder has been quiet since.
    pub fn poll(&mut self) -> bool {
        let now = Instant::now();
        while let Ok((at, event)) = self.events.try_recv() {
            let Ok(event) = event else { continue };
            let wgsl = event
                .paths
                .iter()
                .any(|p| p.extension().is_some_and(|e| e == "wgsl"));
            if wgsl && !matches!(event.kind, notify::EventKind::Access(_)) {
                self.dirty_since = Some(self.dirty_since.map_or(at, |d| d.max(at)));
            }
        }
        match self.dirty_since {
            Some(since) if now.duration_since(since) >= RELOAD_QUIET_PERIOD => {
                self.dirty_since = None;
                true
            }
            _ => false,
        }
    }
}
