//! [`LibraryError`]: why a file could not be opened as a plugin library.

/// Why [`PluginLibrary::open`](crate::host::PluginLibrary::open) failed. The runtime wraps
/// these in sentences that name the file and the plugin.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum LibraryError {
    /// The dynamic loader refused the file (not a shared library, wrong architecture,
    /// missing dependency).
    #[error("the dynamic loader could not open it: {reason}")]
    Open {
        /// The loader's message.
        reason: String,
    },
    /// A shared library, but not an Onyx plugin: it exports no root module.
    #[error("it is a shared library but exports no Onyx plugin (no `export_plugin!`)")]
    MissingRootSymbol,
    /// Built against a plugin-api version this host does not speak.
    #[error("it was built against onyx-plugin-api {built_against}, this host speaks {host}")]
    IncompatibleVersion {
        /// The plugin-api version the plugin was built with.
        built_against: String,
        /// The plugin-api version of this host.
        host: String,
    },
    /// The plugin's types differ from the host's (same version, different definitions).
    #[error("its plugin-api types do not match this host's")]
    IncompatibleLayout {
        /// abi_stable's full report (long; log it at debug level).
        details: String,
    },
    /// Built with an incompatible version of abi_stable itself.
    #[error("it was built with an incompatible abi_stable")]
    IncompatibleAbiStable {
        /// abi_stable's report.
        details: String,
    },
    /// The library's root module failed to initialise.
    #[error("its root module failed to initialise: {message}")]
    InitFailed {
        /// What failed.
        message: String,
    },
}
