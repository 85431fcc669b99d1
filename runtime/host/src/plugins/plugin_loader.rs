//! [`open_library`]: opens a plugin library from disk, through a fresh copy.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use onyx_plugin_api::host::{LibraryError, PluginLibrary, API_VERSION};

use super::plugin_search::name_from_path;
use super::PluginLoadError;

/// Copies `path` to a unique path and opens the copy.
///
/// The dynamic loader returns the already-mapped image when asked for a path it has opened
/// before, and a library is never unloaded (abi_stable leaks it on purpose, and glibc keeps
/// any image that registered a thread-local destructor). So each load — the first, and every
/// hot reload — opens a fresh copy; on Unix the copy is deleted right after opening (the
/// mapping stays valid).
pub fn open_library(path: &Path) -> Result<(PluginLibrary, PathBuf), PluginLoadError> {
    if !path.is_file() {
        return Err(PluginLoadError::MissingFile {
            path: path.to_path_buf(),
        });
    }
    let copy = fresh_copy(path)?;
    // Check the copy (the original may still be changing).
    if let Ok(Some((needed, actual))) = super::library_completeness::truncation(&copy) {
        let _ = std::fs::remove_file(&copy);
        return Err(PluginLoadError::Truncated {
            path: path.to_path_buf(),
            needed,
            actual,
        });
    }
    let opened = PluginLibrary::open(&copy);
    if cfg!(unix) {
        let _ = std::fs::remove_file(&copy);
    }
    let library = opened.map_err(|error| describe(path, error))?;
    Ok((library, copy))
}

fn fresh_copy(path: &Path) -> Result<PathBuf, PluginLoadError> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let copy_error = |source| PluginLoadError::Copy {
        path: path.to_path_buf(),
        source,
    };
    let dir = std::env::temp_dir().join(format!("onyx-plugins-{}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(copy_error)?;
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let file_name = path
        .file_name()
        .map(|f| f.to_string_lossy().into_owned())
        .unwrap_or_else(|| "plugin".into());
    let copy = dir.join(format!("{n}-{file_name}"));
    std::fs::copy(path, &copy).map_err(copy_error)?;
    Ok(copy)
}

fn describe(path: &Path, error: LibraryError) -> PluginLoadError {
    let plugin = name_from_path(path);
    let path = path.to_path_buf();
    match error {
        LibraryError::Open { reason } => PluginLoadError::NotALibrary { path, reason },
        LibraryError::MissingRootSymbol => PluginLoadError::NotAPlugin { path },
        LibraryError::IncompatibleVersion {
            built_against,
            host,
        } => PluginLoadError::IncompatibleApi {
            plugin,
            path,
            built_against,
            host,
        },
        LibraryError::IncompatibleLayout { details } => {
            tracing::debug!(plugin, "abi_stable layout report:\n{details}");
            PluginLoadError::IncompatibleLayout {
                plugin,
                path,
                host: API_VERSION.to_owned(),
                details,
            }
        }
        LibraryError::IncompatibleAbiStable { details } => {
            tracing::debug!(plugin, "abi_stable header report: {details}");
            PluginLoadError::IncompatibleAbiStable {
                plugin,
                path,
                details,
            }
        }
        LibraryError::InitFailed { message } => {
            PluginLoadError::ConstructorFailed { plugin, message }
        }
    }
}
