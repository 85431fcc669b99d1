//! [`AssetWatcher`]: notices edits of the model and texture files being drawn, as
//! [`super::ShaderWatcher`] does for shaders, and says which assets to load again.

use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};
use std::time::Instant;

use onyx_render::SubAsset;

use super::render_assets::AssetKey;
use crate::fs::{FileWatcher, QUIET_PERIOD};

/// Files beside a model that it may read (its material library, textures, glTF buffers):
/// a change to one reloads the models in that folder.
const MODEL_COMPANIONS: [&str; 5] = ["mtl", "png", "jpg", "jpeg", "bin"];

/// Watches the folders of the files being drawn (not recursively; files are watched through
/// their folder, as editors replace files rather than write them in place).
#[derive(Debug)]
pub struct AssetWatcher {
    files: FileWatcher,
    /// Watched folders (canonical).
    dirs: HashSet<PathBuf>,
    /// Each watched file (canonical folder joined with its name) → the assets read from it.
    by_file: HashMap<PathBuf, Vec<AssetKey>>,
    /// Each watched folder → the models read from a file in it.
    models_in: HashMap<PathBuf, Vec<AssetKey>>,
    /// Files changed and not acted on yet, with their last change.
    dirty: HashMap<PathBuf, Instant>,
}

impl AssetWatcher {
    /// A watcher watching nothing yet.
    pub fn new() -> notify::Result<Self> {
        Ok(Self {
            files: FileWatcher::new()?,
            dirs: HashSet::new(),
            by_file: HashMap::new(),
            models_in: HashMap::new(),
            dirty: HashMap::new(),
        })
    }

    /// Watches the files `assets` were read from (the models and textures drawn), in
    /// place of those watched before.
    pub(crate) fn watch(&mut self, assets: &[(AssetKey, PathBuf)]) {
        self.by_file.clear();
        self.models_in.clear();
        for (key, path) in assets {
            let (file, _) = SubAsset::split(path);
            let (Some(dir), Some(name)) = (file.parent(), file.file_name()) else {
                continue;
            };
            let dir = if dir.as_os_str().is_empty() {
                Path::new(".")
            } else {
                dir
            };
            let Ok(dir) = std::fs::canonicalize(dir) else {
                continue;
            };
            if !self.dirs.contains(&dir) {
                match self.files.watch_dir(&dir) {
                    Ok(()) => {
                        self.dirs.insert(dir.clone());
                    }
                    Err(error) => {
                        tracing::warn!(dir = %dir.display(), %error, "asset changes there will not be picked up");
                        continue;
                    }
                }
            }
            self.by_file.entry(dir.join(name)).or_default().push(*key);
            if matches!(key, AssetKey::Mesh(_)) {
                self.models_in.entry(dir).or_default().push(*key);
            }
        }
    }

    /// The assets whose files changed and have been quiet for [`QUIET_PERIOD`] since, each
    /// once.
    pub(crate) fn poll(&mut self) -> Vec<AssetKey> {
        let dirty = &mut self.dirty;
        self.files.drain(|at, path| {
            let last = dirty.entry(path.to_path_buf()).or_insert(at);
            *last = (*last).max(at);
        });
        let now = Instant::now();
        let settled: Vec<PathBuf> = self
            .dirty
            .iter()
            .filter(|(_, at)| now.duration_since(**at) >= QUIET_PERIOD)
            .map(|(path, _)| path.clone())
            .collect();
        let mut changed = Vec::new();
        for path in settled {
            self.dirty.remove(&path);
            let mut add = |keys: &[AssetKey]| {
                for key in keys {
                    if !changed.contains(key) {
                        changed.push(*key);
                    }
                }
            };
            if let Some(keys) = self.by_file.get(&path) {
                add(keys);
            }
            let companion = path
                .extension()
                .and_then(|e| e.to_str())
                .is_some_and(|e| MODEL_COMPANIONS.iter().any(|c| e.eq_ignore_ascii_case(c)));
            if companion {
                if let Some(keys) = path.parent().and_then(|dir| self.models_in.get(dir)) {
                    add(keys);
                }
            }
        }
        changed
    }
}
