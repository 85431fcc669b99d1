//! [`open_library`]: opens a plugin library from disk, through a fresh copy.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use onyx_plugin_api::host::{LibraryError, PluginLibrary, API_VERSION};

use super::library_check::LibraryProblem;
use super::plugin_search::name_from_path;
use super::{PluginLoadError, Stage};
use crate::watchdog::plugin_call::PluginCall;
use crate::watchdog::CallTag;

/// Copies `path` to a unique path and opens the copy.
///
/// The dynamic loader returns the already-mapped image when asked for a path it has opened
/// before, and a library is never unloaded (abi_stable leaks it on purpose, and glibc keeps
/// any image that registered a thread-local destructor). So each load — the first, and every
/// hot reload — opens a fresh copy; on Unix the copy is deleted right after opening (the
/// mapping stays valid).
pub fn open_library(path: &Path) -> Result<(PluginLibrary, PathBuf), PluginLoadError> {
    match std::fs::metadata(path) {
        Err(_) => {
            return Err(PluginLoadError::MissingFile {
                path: path.to_path_buf(),
            })
        }
        Ok(m) if !m.is_file() => {
            return Err(PluginLoadError::NotAFile {
                path: path.to_path_buf(),
                kind: if m.is_dir() {
                    "a directory"
                } else {
                    "not a regular file (a device, FIFO or socket)"
                },
            })
        }
        Ok(_) => {}
    }
    // One load at a time in this process: the copy folder is emptied and removed after each
    // load, which must not race another load copying into it.
    static LOADING: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _loading = LOADING
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let copy = fresh_copy(path)?;
    // Check the copy (the original may still be changing) before the loader trusts it.
    let checked = match super::library_check::check_library_file(&copy) {
        Ok(Ok(())) => Ok(()),
        Ok(Err(LibraryProblem::Truncated { needed, actual })) => Err(PluginLoadError::Truncated {
            path: path.to_path_buf(),
            needed,
            actual,
        }),
        Ok(Err(LibraryProblem::Damaged(problem))) => Err(PluginLoadError::Damaged {
            path: path.to_path_buf(),
            problem,
        }),
        Err(cause) => Err(PluginLoadError::Copy {
            path: path.to_path_buf(),
            cause,
        }),
    };
    if let Err(error) = checked {
        let _ = std::fs::remove_file(&copy);
        if let Some(dir) = copy.parent() {
            let _ = std::fs::remove_dir(dir);
        }
        return Err(error);
    }
    // The system loader maps it and runs its initialisers: a crash in there names the file.
    let opened = {
        let _call = PluginCall::enter(CallTag::library(path), Stage::Load);
        PluginLibrary::open(&copy)
    };
    if cfg!(unix) {
        let _ = std::fs::remove_file(&copy);
        // Empty again on Unix (the mapping outlives the file): nothing is left behind.
        if let Some(dir) = copy.parent() {
            let _ = std::fs::remove_dir(dir);
        }
    }
    let library = opened.map_err(|error| describe(path, error))?;
    Ok((library, copy))
}

/// The folder prefix of the fresh copies, followed by the process id.
const COPY_DIR_PREFIX: &str = "onyx-plugins-";

fn fresh_copy(path: &Path) -> Result<PathBuf, PluginLoadError> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    static SWEPT: std::sync::Once = std::sync::Once::new();
    SWEPT.call_once(remove_stale_copy_dirs);
    let copy_error = |cause| PluginLoadError::Copy {
        path: path.to_path_buf(),
        cause,
    };
    let dir = std::env::temp_dir().join(format!("{COPY_DIR_PREFIX}{}", std::process::id()));
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

/// Removes the copy folders of processes that no longer run (a crash, a kill, or a platform
/// where a mapped file cannot be deleted). Where it cannot tell whether a process runs
/// (no `/proc`), it leaves the folders alone.
fn remove_stale_copy_dirs() {
    let proc = Path::new("/proc");
    if !proc.join("self").exists() {
        return;
    }
    let Ok(entries) = std::fs::read_dir(std::env::temp_dir()) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(pid) = name
            .to_str()
            .and_then(|n| n.strip_prefix(COPY_DIR_PREFIX))
            .and_then(|pid| pid.parse::<u32>().ok())
        else {
            continue;
        };
        if pid != std::process::id() && !proc.join(pid.to_string()).exists() {
            match std::fs::remove_dir_all(entry.path()) {
                Ok(()) => {
                    tracing::debug!(dir = %entry.path().display(), "removed stale plugin copies")
                }
                Err(e) => {
                    tracing::debug!(dir = %entry.path().display(), "cannot remove stale plugin copies: {e}")
                }
            }
        }
    }
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
