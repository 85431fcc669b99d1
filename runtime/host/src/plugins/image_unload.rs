//! [`unload_image`]: hands an old build's library image back to the system loader once
//! nothing from it can run again, and says what became of it ([`ImageFate`]).
//!
//! When it is safe, and how the host knows:
//!
//! - **No object from it**: the only objects a library hands the host are plugin objects;
//!   everything else that crosses the boundary (events, components, GUI meshes and textures,
//!   errors, saved state) is copied into host memory. Each `PluginInstance` holds the image;
//!   `PluginLibrary::close` refuses while one is alive, and the host drops the old build's
//!   object (inside its image) and forgets its GUI before it gets here.
//! - **No call into it on any stack**: the host calls plugins from its frame loop only, and a
//!   swap runs between calls.
//! - **abi_stable's layout-check cache**: abi_stable keeps, for the whole process, the layouts
//!   of the prefix types it checked. Between a host and a library built against the *same*
//!   onyx-plugin-api version the two layouts have the same fields and the cache keeps the
//!   host's own (`min_max` keeps the interface on a tie); a library built against another
//!   patch version may have more fields, and then its layout is what stays cached. So only a
//!   library built against exactly this host's version is unloaded.
//! - **Signal handlers**: a handler it installed and left in place would jump into unmapped
//!   memory; every signal's handler is read first, and an image holding one is kept.
//! - **Threads and thread-local destructors**: glibc keeps an image mapped while a
//!   thread-local destructor it registered is pending (`__cxa_thread_atexit_impl` holds the
//!   image). Rust's std registers one on every thread it starts, so a thread the plugin
//!   started and did not stop in `on_detach` keeps its image mapped, safely, as does a
//!   thread-local with a destructor that the plugin filled on the host's thread — and std
//!   fills one itself on the thread that calls `std::thread::spawn` (its list of spawn
//!   hooks), so a plugin that ever spawned a thread from a plugin call keeps its image until
//!   the host's thread ends, even when it stops the thread in `on_detach`. glibc unmaps such
//!   an image at a later close once its destructors have run. The host checks afterwards
//!   whether the image really left (`dl_iterate_phdr`) and reports it ([`ImageFate::Pinned`]).
//! - **What it cannot see**: threads started outside Rust's std (a C library's, a raw
//!   `pthread_create`), or callbacks handed to a C library and not taken back: a plugin must
//!   stop and unregister those in `on_detach` (the README says so), or the old image crashes
//!   the host when they run. [`HostConfig::keep_old_builds`](crate::HostConfig) keeps every
//!   old image mapped for such plugins.
//!
//! Elsewhere (not glibc) images stay mapped, as before.

use std::path::Path;

use onyx_plugin_api::host::{PluginLibrary, API_VERSION};

/// What became of an old build's image after a swap (or an unload).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ImageFate {
    /// Handed back and unmapped: its memory is free.
    Unmapped,
    /// Handed back, but the system loader keeps it mapped (a thread-local destructor it
    /// registered is still pending: a thread it started still runs, or it filled a
    /// thread-local with a destructor on a thread that still does — std's `spawn` fills one
    /// on the calling thread).
    Pinned,
    /// Not handed back, for the reason given.
    Kept(String),
    /// To be handed back at the end of the frame that swapped it out (an automatic reload);
    /// the swap's report then says what became of it.
    AfterFrame,
}

impl std::fmt::Display for ImageFate {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ImageFate::Unmapped => f.write_str("unmapped"),
            ImageFate::Pinned => f.write_str(
                "still mapped: the system loader keeps it while a thread-local destructor it \
                 registered is pending (a thread it started has not ended, or it filled a \
                 thread-local on a thread that still runs, as Rust's std does on a thread \
                 that spawns one)",
            ),
            ImageFate::Kept(reason) => write!(f, "kept mapped: {reason}"),
            ImageFate::AfterFrame => f.write_str("handed back at the end of this frame"),
        }
    }
}

/// Closes `library` (opened from the copy at `loaded_from`) if nothing from it can run again
/// (see the module docs); `keep` keeps it mapped regardless.
pub(crate) fn unload_image(library: PluginLibrary, loaded_from: &Path, keep: bool) -> ImageFate {
    if keep {
        return leak(
            library,
            "the host keeps old builds mapped (keep_old_builds)",
        );
    }
    if !cfg!(all(target_os = "linux", target_env = "gnu")) {
        return leak(library, "unloading is only done on Linux with glibc");
    }
    if library.api_version() != API_VERSION {
        let reason = format!(
            "it was built against onyx-plugin-api {}, not this host's {API_VERSION} \
             (abi_stable's layout cache may point into it)",
            library.api_version()
        );
        return leak(library, &reason);
    }
    let Some(segments) = loaded::segments(loaded_from) else {
        return leak(library, "the system loader does not list it");
    };
    if let Some(signal) = loaded::signal_handler_in(&segments) {
        let reason = format!("it installed the handler of signal {signal}");
        return leak(library, &reason);
    }
    // SAFETY: the conditions of `close` are what this module checks (its docs list them):
    // no plugin object from the image is alive (`close` checks), no call into it is running
    // (the frame loop is between calls), abi_stable's cache holds only the host's layouts
    // (same API version), no signal handler points into it, and glibc keeps it mapped while
    // a thread Rust's std started from it still runs. Threads and callbacks outside std are
    // the plugin's to stop in `on_detach`.
    match unsafe { library.close() } {
        Ok(()) if loaded::segments(loaded_from).is_some() => ImageFate::Pinned,
        Ok(()) => ImageFate::Unmapped,
        Err(library) => leak(library, "a plugin object built from it is still alive"),
    }
}

fn leak(library: PluginLibrary, reason: &str) -> ImageFate {
    drop(library); // the image stays mapped: a `PluginLibrary` never unmaps on drop
    ImageFate::Kept(reason.to_owned())
}

#[cfg(all(target_os = "linux", target_env = "gnu"))]
mod loaded {
    use std::ffi::{c_int, c_void, CStr};
    use std::ops::Range;
    use std::os::unix::ffi::OsStrExt as _;
    use std::path::Path;

    struct Search<'a> {
        name: &'a [u8],
        found: Option<Vec<Range<usize>>>,
    }

    unsafe extern "C" fn visit(
        info: *mut libc::dl_phdr_info,
        _size: usize,
        data: *mut c_void,
    ) -> c_int {
        // SAFETY: `data` is the `Search` that `segments` passed, alive for the whole
        // iteration; `info` and what it points to are valid during the callback.
        let (search, info) = unsafe { (&mut *data.cast::<Search<'_>>(), &*info) };
        if info.dlpi_name.is_null() {
            return 0;
        }
        // SAFETY: the loader's names are NUL-terminated strings it keeps while listed.
        let name = unsafe { CStr::from_ptr(info.dlpi_name) };
        if name.to_bytes() != search.name {
            return 0;
        }
        let mut ranges = Vec::new();
        for i in 0..usize::from(info.dlpi_phnum) {
            // SAFETY: the loader lists `dlpi_phnum` program headers at `dlpi_phdr`.
            let header = unsafe { &*info.dlpi_phdr.add(i) };
            if header.p_type == libc::PT_LOAD {
                let start = (info.dlpi_addr as usize).wrapping_add(header.p_vaddr as usize);
                ranges.push(start..start.wrapping_add(header.p_memsz as usize));
            }
        }
        search.found = Some(ranges);
        1
    }

    /// The address ranges of the loaded object opened from `path`, if it is loaded.
    pub(super) fn segments(path: &Path) -> Option<Vec<Range<usize>>> {
        let mut search = Search {
            name: path.as_os_str().as_bytes(),
            found: None,
        };
        // SAFETY: `visit` matches the callback type and only reads what it is given;
        // `search` outlives the call.
        unsafe { libc::dl_iterate_phdr(Some(visit), (&raw mut search).cast()) };
        search.found
    }

    /// The first signal whose handler lies in `segments`.
    pub(super) fn signal_handler_in(segments: &[Range<usize>]) -> Option<c_int> {
        (1..=libc::SIGRTMAX()).find(|&signal| {
            // SAFETY: `sigaction` with a null new action only reads the current one into a
            // zeroed struct of the right type.
            let handler = unsafe {
                let mut current: libc::sigaction = std::mem::zeroed();
                if libc::sigaction(signal, std::ptr::null(), &mut current) != 0 {
                    return false;
                }
                current.sa_sigaction
            };
            handler > libc::SIG_IGN && segments.iter().any(|r| r.contains(&handler))
        })
    }
}

#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
mod loaded {
    use std::ops::Range;
    use std::path::Path;

    pub(super) fn segments(_path: &Path) -> Option<Vec<Range<usize>>> {
        None
    }

    pub(super) fn signal_handler_in(_segments: &[Range<usize>]) -> Option<i32> {
        None
    }
}

/// An old build's image swapped out by an automatic reload, waiting for the end of the frame
/// to be handed back to the system loader (its plugin object is already dropped and nothing
/// calls into it: the slot holds the new build).
pub(crate) struct RetiredImage {
    /// The plugin it was a build of.
    pub(crate) name: String,
    /// The image.
    pub(crate) library: onyx_plugin_api::host::PluginLibrary,
    /// The file it was mapped from (the host's own copy).
    pub(crate) loaded_from: std::path::PathBuf,
}
