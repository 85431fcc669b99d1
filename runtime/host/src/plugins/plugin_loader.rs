//! [`open_library`]: opens a plugin library from disk, through a fresh copy; [`OpenedLibrary`]
//! and [`LoadTimings`], what it made and where its time went.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

use onyx_plugin_api::host::{LibraryError, PluginLibrary, API_VERSION};

use super::library_check::LibraryProblem;
use super::plugin_search::name_from_path;
use super::{PluginLoadError, Stage};
use crate::watchdog::plugin_call::PluginCall;
use crate::watchdog::CallTag;

/// A library opened by [`open_library`].
#[derive(Debug)]
pub struct OpenedLibrary {
    /// The opened, checked library.
    pub library: PluginLibrary,
    /// The unique copy that was opened (deleted again on Unix; the mapping outlives it).
    pub loaded_from: PathBuf,
    /// [`content_hash`] of the bytes that were loaded.
    pub content_hash: u64,
    /// Where the time went.
    pub timings: LoadTimings,
}

/// The stages of [`open_library`], timed.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LoadTimings {
    /// Mapping the file (once, read-only) and hashing it.
    pub read: Duration,
    /// The ELF check of the bytes read (`library_check`).
    pub check: Duration,
    /// Writing the fresh copy.
    pub copy: Duration,
    /// The system loader mapping and relocating the copy, and abi_stable's version and
    /// layout checks of its root module.
    pub map: Duration,
}

/// A hash of a library's bytes, to tell a rebuild that changed nothing (a `touch`, a no-op
/// link) from a new build: CRC-32 (hardware-assisted, fast enough to run on every rebuild of
/// a large debug library) with the length. Not a defence against crafted collisions: a
/// collision only means a rebuild is not reloaded by itself.
pub fn content_hash(bytes: &[u8]) -> u64 {
    (u64::from(crc32fast::hash(bytes)) << 32) ^ bytes.len() as u64
}

/// Reads `path`, checks it and opens it through a copy at a unique path (of the part the
/// loader maps, `library_check::loaded_part`).
///
/// The dynamic loader returns the already-mapped image when asked for a path it has opened
/// before, so each load — the first, and every hot reload — opens a fresh copy; on Unix the
/// copy is deleted right after opening (the mapping stays valid). The file is mapped once
/// (see [`read_library`]): the hash, the ELF check and the copy all come from the same
/// mapping, and the check touches only the pages of the tables it reads.
pub fn open_library(path: &Path) -> Result<OpenedLibrary, PluginLoadError> {
    let started = Instant::now();
    let bytes = read_library(path)?;
    let hash = content_hash(&bytes);
    let read = started.elapsed();
    open_library_bytes(path, &bytes, hash, read)
}

/// A library file mapped read-only: its bytes without copying them into the heap.
pub(crate) type LibraryBytes = memmap2::Mmap;

/// Maps a library file read-only, refusing what is not a regular file.
///
/// Mapping instead of reading saves a copy of the whole file (a debug plugin is mostly debug
/// info the loader never reads): the page cache is read in place, and only the pages the
/// hash, the check and the copy touch are faulted in. The watcher only reports a file its
/// own headers say is complete, and build tools replace a library rather than rewrite it in
/// place (cargo hard-links or copies a fresh file over it; linkers write a new file), so the
/// mapping does not change while it is used.
pub(crate) fn read_library(path: &Path) -> Result<LibraryBytes, PluginLoadError> {
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
    let read_error = |cause| PluginLoadError::Read {
        path: path.to_path_buf(),
        cause,
    };
    let file = std::fs::File::open(path).map_err(read_error)?;
    // SAFETY: the mapping is read-only and private to this process; the bytes are only read
    // as plain data (hashed, parsed with bounds checks, written to the copy), never trusted
    // as Rust values. See above for why the file is not rewritten while it is mapped.
    unsafe { memmap2::Mmap::map(&file) }.map_err(read_error)
}

/// [`open_library`] for bytes already read from `path` (hashing to `hash`, read in `read`).
pub(crate) fn open_library_bytes(
    path: &Path,
    bytes: &[u8],
    hash: u64,
    read: Duration,
) -> Result<OpenedLibrary, PluginLoadError> {
    let mut timings = LoadTimings {
        read,
        ..LoadTimings::default()
    };
    // Checked before the loader trusts it.
    let started = Instant::now();
    let checked = match super::library_check::check_library(bytes) {
        Ok(()) => Ok(()),
        Err(LibraryProblem::Truncated { needed, actual }) => Err(PluginLoadError::Truncated {
            path: path.to_path_buf(),
            needed,
            actual,
        }),
        Err(LibraryProblem::Damaged(problem)) => Err(PluginLoadError::Damaged {
            path: path.to_path_buf(),
            problem,
        }),
    };
    timings.check = started.elapsed();
    checked?;
    // One load at a time in this process: the copy folder is emptied and removed after each
    // load, which must not race another load copying into it.
    static LOADING: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _loading = LOADING
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let started = Instant::now();
    let copy = fresh_copy(path, bytes)?;
    timings.copy = started.elapsed();
    // The system loader maps it and runs its initialisers: a crash in there names the file.
    let started = Instant::now();
    let opened = {
        let _call = PluginCall::enter(CallTag::library(path), Stage::Load);
        PluginLibrary::open(&copy)
    };
    timings.map = started.elapsed();
    if cfg!(unix) {
        let _ = std::fs::remove_file(&copy);
        // Empty again on Unix (the mapping outlives the file): nothing is left behind.
        if let Some(dir) = copy.parent() {
            let _ = std::fs::remove_dir(dir);
        }
    }
    let library = opened.map_err(|error| describe(path, error))?;
    Ok(OpenedLibrary {
        library,
        loaded_from: copy,
        content_hash: hash,
        timings,
    })
}

/// The folder prefix of the fresh copies, followed by the process id.
const COPY_DIR_PREFIX: &str = "onyx-plugins-";

/// A copy, not a hard link to the user's file: a linked image shares the file's inode for as
/// long as it is mapped, and anything that later rewrites the file in place (`cp`, a test
/// writing a cut build over it, an editor) would truncate or change the running build's
/// code under it — a crash, not a refused reload. A copy in the host's own folder is
/// written by nobody else.
fn fresh_copy(path: &Path, bytes: &[u8]) -> Result<PathBuf, PluginLoadError> {
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
    // Only what the loader maps (see `loaded_part`): the file was checked whole already.
    let written = match super::library_check::loaded_part(bytes) {
        Some((end, header)) => {
            use std::io::Write as _;
            std::fs::File::create(&copy).and_then(|mut file| {
                file.write_all(&header)?;
                file.write_all(&bytes[header.len()..end])
            })
        }
        None => std::fs::write(&copy, bytes),
    };
    written.map_err(copy_error)?;
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
