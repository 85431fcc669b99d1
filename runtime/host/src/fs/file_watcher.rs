//! [`FileWatcher`]: change events for watched folders, each stamped with when it happened.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{channel, Receiver};
use std::time::{Duration, Instant};

use notify::{RecursiveMode, Watcher};

/// How long a file must go without change events before it counts as settled: editors save
/// and cargo links in several pieces, and acting on the first piece would read half a file.
pub const QUIET_PERIOD: Duration = Duration::from_millis(10);

/// Watches folders (not recursively; files are watched through their folder, as builds and
/// editors replace files rather than write them in place) and hands out the paths that
/// changed. Watching a folder twice is counted, so it is unwatched once both are done.
pub struct FileWatcher {
    watcher: notify::RecommendedWatcher,
    /// Events, stamped with when they happened (not when they were read).
    events: Receiver<(Instant, notify::Result<notify::Event>)>,
    dirs: HashMap<PathBuf, usize>,
}

impl std::fmt::Debug for FileWatcher {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("FileWatcher")
            .field("dirs", &self.dirs.keys().collect::<Vec<_>>())
            .finish()
    }
}

impl FileWatcher {
    /// A watcher watching nothing yet.
    pub fn new() -> notify::Result<Self> {
        let (tx, events) = channel();
        let watcher = notify::recommended_watcher(move |event| {
            let _ = tx.send((Instant::now(), event));
        })?;
        Ok(Self {
            watcher,
            events,
            dirs: HashMap::new(),
        })
    }

    /// Starts watching `dir`.
    pub fn watch_dir(&mut self, dir: &Path) -> notify::Result<()> {
        if !self.dirs.contains_key(dir) {
            self.watcher.watch(dir, RecursiveMode::NonRecursive)?;
        }
        *self.dirs.entry(dir.to_path_buf()).or_default() += 1;
        Ok(())
    }

    /// Stops one watch of `dir`.
    pub fn unwatch_dir(&mut self, dir: &Path) {
        if let Some(count) = self.dirs.get_mut(dir) {
            *count -= 1;
            if *count == 0 {
                self.dirs.remove(dir);
                let _ = self.watcher.unwatch(dir);
            }
        }
    }

    /// Calls `changed` with each path written, created, removed or renamed since the last
    /// call (reads are not changes), and when that happened.
    pub fn drain(&mut self, mut changed: impl FnMut(Instant, &Path)) {
        while let Ok((at, event)) = self.events.try_recv() {
            let Ok(event) = event else { continue };
            if matches!(event.kind, notify::EventKind::Access(_)) {
                continue;
            }
            for path in &event.paths {
                changed(at, path);
            }
        }
    }
}
