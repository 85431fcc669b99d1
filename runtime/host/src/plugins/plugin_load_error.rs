//! [`PluginLoadError`]: why a plugin could not be loaded, as a sentence a person can act on.

use std::path::PathBuf;

fn list(paths: &[PathBuf]) -> String {
    paths
        .iter()
        .map(|p| format!("`{}`", p.display()))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Why a plugin was not loaded. The host logs it, raises a platform event and goes on.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PluginLoadError {
    /// No library for the plugin name in the search path.
    #[error(
        "plugin `{name}` not found; looked for {}. Build it (`cargo build -p {name}`) or add \
         its directory to ONYX_PLUGIN_PATH",
        list(.searched)
    )]
    NotFound {
        /// The name asked for.
        name: String,
        /// Every file tried.
        searched: Vec<PathBuf>,
    },
    /// The path given does not exist.
    #[error("plugin file `{}` does not exist: check the path, or build the plugin first", .path.display())]
    MissingFile {
        /// The path given.
        path: PathBuf,
    },
    /// The path names a directory, a device, a FIFO or a socket, not a library file.
    #[error(
        "`{}` is {kind}, not a plugin library file: pass the library itself, e.g. \
         `target/debug/libNAME.so` (`onyx plugins` lists the ones it finds)",
        .path.display()
    )]
    NotAFile {
        /// The path given.
        path: PathBuf,
        /// What it is ("a directory", …).
        kind: &'static str,
    },
    /// The file is not a loadable shared library.
    #[error(
        "`{}` is not a shared library the loader can open ({reason}); pass the `.so`/`.dylib`/`.dll` \
         of a crate built with crate-type = [\"cdylib\"]",
        .path.display()
    )]
    NotALibrary {
        /// The file.
        path: PathBuf,
        /// The dynamic loader's message.
        reason: String,
    },
    /// The file is shorter than its own headers say: a build still being written, or cut off.
    #[error(
        "`{}` is incomplete ({actual} of {needed} bytes): it is still being written or was cut \
         off; rebuild it",
        .path.display()
    )]
    Truncated {
        /// The file.
        path: PathBuf,
        /// Bytes its headers require.
        needed: u64,
        /// Bytes it has.
        actual: u64,
    },
    /// The file's headers or tables are damaged where the system loader would crash on them.
    #[error(
        "`{}` is damaged: {problem}; the system loader would crash on it, so it was not \
         opened. Rebuild it",
        .path.display()
    )]
    Damaged {
        /// The file.
        path: PathBuf,
        /// What is wrong, in words.
        problem: String,
    },
    /// A shared library without the Onyx root module.
    #[error(
        "`{}` is a shared library but not an Onyx plugin: it exports no plugin root module. Add \
         `onyx_plugin_api::export_plugin!(YourPlugin);` to the crate and rebuild it",
        .path.display()
    )]
    NotAPlugin {
        /// The file.
        path: PathBuf,
    },
    /// Built against another plugin-api version.
    #[error(
        "plugin `{plugin}` was built against onyx-plugin-api {built_against}, this host speaks \
         {host}: rebuild it against onyx-plugin-api {host} (file `{}`)",
        .path.display()
    )]
    IncompatibleApi {
        /// The plugin (from the file name).
        plugin: String,
        /// The file.
        path: PathBuf,
        /// Its plugin-api version.
        built_against: String,
        /// This host's plugin-api version.
        host: String,
    },
    /// Same version but different type layouts (a modified or forked plugin-api).
    #[error(
        "plugin `{plugin}` was built against a different onyx-plugin-api {host} than this host's \
         (its types do not match): rebuild it against this host's onyx-plugin-api (file `{}`; \
         run with RUST_LOG=debug for the full layout report)",
        .path.display()
    )]
    IncompatibleLayout {
        /// The plugin (from the file name).
        plugin: String,
        /// The file.
        path: PathBuf,
        /// This host's plugin-api version.
        host: String,
        /// abi_stable's report (logged at debug level).
        details: String,
    },
    /// Built with an incompatible abi_stable.
    #[error(
        "plugin `{plugin}` was built with an abi_stable release this host cannot read: rebuild \
         it against this host's onyx-plugin-api (file `{}`)",
        .path.display()
    )]
    IncompatibleAbiStable {
        /// The plugin (from the file name).
        plugin: String,
        /// The file.
        path: PathBuf,
        /// abi_stable's report.
        details: String,
    },
    /// The library failed to initialise, or the plugin's constructor panicked.
    #[error("plugin `{plugin}` failed while being created: {message}")]
    ConstructorFailed {
        /// The plugin.
        plugin: String,
        /// What failed.
        message: String,
    },
    /// `on_attach` panicked or returned an error.
    #[error("plugin `{plugin}` failed in on_attach: {message}")]
    AttachFailed {
        /// The plugin.
        plugin: String,
        /// The panic or error message.
        message: String,
    },
    /// A plugin of that name is already loaded.
    #[error("plugin `{plugin}` is already loaded; a name can be loaded once")]
    AlreadyLoaded {
        /// The plugin.
        plugin: String,
    },
    /// The file could not be read.
    #[error("cannot read `{}`: {cause}", .path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// The I/O error (in the sentence, not chained as a `source`).
        cause: std::io::Error,
    },
    /// The file could not be copied to a fresh path for loading.
    #[error("could not copy `{}` to a fresh path for loading: {cause}", .path.display())]
    Copy {
        /// The file.
        path: PathBuf,
        /// The I/O error (in the sentence, not chained as a `source`).
        cause: std::io::Error,
    },
}
