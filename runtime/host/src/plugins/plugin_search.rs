//! [`PluginSearchPath`]: how a plugin NAME becomes a library file.

use std::path::{Path, PathBuf};

/// Environment variable listing extra plugin directories (`:`-separated on Unix, `;` on
/// Windows), searched first.
pub const PLUGIN_PATH_VAR: &str = "ONYX_PLUGIN_PATH";

/// The directories searched for a plugin given by name, in order:
///
/// 1. each directory in `ONYX_PLUGIN_PATH`;
/// 2. the directory of the running executable (cargo puts `onyx` and the plugin libraries
///    side by side in `target/<profile>/`), and its parent when the executable sits in
///    `deps/` (test binaries);
/// 3. the workspace's build output: `$CARGO_TARGET_DIR/{debug,release}` if set, else
///    `./target/{debug,release}`.
#[derive(Clone, Debug, Default)]
pub struct PluginSearchPath {
    dirs: Vec<PathBuf>,
}

impl PluginSearchPath {
    /// The documented search path, read from the environment.
    pub fn from_env() -> Self {
        let mut dirs = Vec::new();
        if let Some(list) = std::env::var_os(PLUGIN_PATH_VAR) {
            dirs.extend(std::env::split_paths(&list).filter(|p| !p.as_os_str().is_empty()));
        }
        if let Some(exe_dir) = std::env::current_exe()
            .ok()
            .and_then(|exe| exe.parent().map(Path::to_path_buf))
        {
            if exe_dir.file_name().is_some_and(|n| n == "deps") {
                if let Some(parent) = exe_dir.parent() {
                    dirs.push(parent.to_path_buf());
                }
            }
            dirs.push(exe_dir);
        }
        let target = std::env::var_os("CARGO_TARGET_DIR")
            .map(PathBuf::from)
            .unwrap_or_else(|| PathBuf::from("target"));
        dirs.push(target.join("debug"));
        dirs.push(target.join("release"));
        Self {
            dirs: without_repeats(dirs),
        }
    }

    /// A search path of exactly these directories.
    pub fn new(dirs: Vec<PathBuf>) -> Self {
        Self { dirs }
    }

    /// The directories, in search order.
    pub fn dirs(&self) -> &[PathBuf] {
        &self.dirs
    }

    /// The first existing library file for plugin `name`, or the candidates that were tried.
    pub fn find(&self, name: &str) -> Result<PathBuf, Vec<PathBuf>> {
        let file = library_file_name(name);
        let candidates: Vec<PathBuf> = self.dirs.iter().map(|d| d.join(&file)).collect();
        candidates
            .iter()
            .find(|p| p.is_file())
            .cloned()
            .ok_or(candidates)
    }
}

/// `dirs` with each directory once, at its first place: the same directory named twice
/// (`target/debug` beside the executable's own `/…/target/debug`) is searched once.
fn without_repeats(dirs: Vec<PathBuf>) -> Vec<PathBuf> {
    let key = |dir: &Path| {
        dir.canonicalize()
            .or_else(|_| std::path::absolute(dir))
            .unwrap_or_else(|_| dir.to_path_buf())
    };
    let mut seen = Vec::new();
    dirs.into_iter()
        .filter(|dir| {
            let k = key(dir);
            let new = !seen.contains(&k);
            seen.push(k);
            new
        })
        .collect()
}

/// The file cargo builds for cdylib crate `name` on this platform: `libNAME.so`,
/// `libNAME.dylib` or `NAME.dll`, with `-` turned into `_`.
pub fn library_file_name(name: &str) -> String {
    let stem = name.replace('-', "_");
    format!(
        "{}{stem}{}",
        std::env::consts::DLL_PREFIX,
        std::env::consts::DLL_SUFFIX
    )
}

/// Whether a `--plugin` argument names a file rather than a plugin.
pub fn looks_like_path(arg: &str) -> bool {
    arg.contains('/')
        || arg.contains(std::path::MAIN_SEPARATOR)
        || arg.ends_with(std::env::consts::DLL_SUFFIX)
}

/// The plugin name a library file is expected to hold (`libfoo_bar.so` → `foo_bar`).
pub fn name_from_path(path: &Path) -> String {
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    stem.strip_prefix(std::env::consts::DLL_PREFIX)
        .filter(|_| !std::env::consts::DLL_PREFIX.is_empty())
        .map(str::to_owned)
        .unwrap_or(stem)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_map_to_platform_library_files_and_back() {
        let file = library_file_name("my-plugin");
        assert!(file.contains("my_plugin"), "{file}");
        assert_eq!(name_from_path(Path::new(&file)), "my_plugin");
        assert!(looks_like_path(&file));
        assert!(looks_like_path("./x"));
        assert!(!looks_like_path("hello"));
    }

    /// `onyx plugins` listed `target/debug` twice: once as the executable's folder, once as
    /// `./target/debug`.
    #[test]
    fn a_directory_named_twice_is_searched_once() {
        let dir = tempfile::tempdir().unwrap();
        let inner = dir.path().join("debug");
        std::fs::create_dir(&inner).unwrap();
        let cwd = std::env::current_dir().unwrap();
        let relative = pathdiff(&inner, &cwd);
        let other = tempfile::tempdir().unwrap();
        let dirs = without_repeats(vec![
            inner.clone(),
            other.path().to_path_buf(),
            relative,
            inner.join("."),
        ]);
        assert_eq!(dirs, vec![inner, other.path().to_path_buf()]);
    }

    /// `path` relative to `base` (both absolute), with `..` as needed.
    fn pathdiff(path: &Path, base: &Path) -> PathBuf {
        let path: Vec<_> = path.components().collect();
        let base: Vec<_> = base.components().collect();
        let common = path.iter().zip(&base).take_while(|(a, b)| a == b).count();
        let mut out = PathBuf::new();
        for _ in common..base.len() {
            out.push("..");
        }
        for part in &path[common..] {
            out.push(part);
        }
        out
    }

    #[test]
    fn find_returns_the_first_directory_holding_the_file_or_every_candidate() {
        let a = tempfile::tempdir().unwrap();
        let b = tempfile::tempdir().unwrap();
        let file = library_file_name("p");
        std::fs::write(b.path().join(&file), b"x").unwrap();
        let search = PluginSearchPath::new(vec![a.path().into(), b.path().into()]);
        assert_eq!(search.find("p").unwrap(), b.path().join(&file));
        let tried = search.find("q").unwrap_err();
        assert_eq!(tried.len(), 2);
    }
}
