//! [`ReloadError`]: why a new build did not replace a running plugin.

use std::path::PathBuf;

use super::PluginLoadError;

/// A hot reload that did not happen. In every case the previous build keeps running (or
/// stays faulted, if it was).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ReloadError {
    /// No plugin of that name is loaded.
    #[error("no plugin `{plugin}` is loaded")]
    NotLoaded {
        /// The name asked for.
        plugin: String,
    },
    /// The plugin was added in-process, so there is no file to reload.
    #[error("plugin `{plugin}` was not loaded from a file, so it cannot be reloaded")]
    NotFromFile {
        /// The plugin.
        plugin: String,
    },
    /// The new file could not be loaded.
    #[error("the new build of plugin `{plugin}` could not be loaded: {cause}")]
    Load {
        /// The plugin.
        plugin: String,
        /// Why.
        cause: Box<PluginLoadError>,
    },
    /// The file now holds another plugin.
    #[error(
        "`{}` now holds plugin `{found}`, not `{plugin}`: load it as a new plugin instead",
        .path.display()
    )]
    NameChanged {
        /// The running plugin.
        plugin: String,
        /// The name in the new file.
        found: String,
        /// The file.
        path: PathBuf,
    },
    /// The new build could not read the running build's saved state (`load_state` returned
    /// an error: a field of another type, a state type it cannot map).
    #[error(
        "plugin `{plugin}` was not reloaded: its new build cannot read the state of the running \
         one: {message}"
    )]
    StateRefused {
        /// The plugin.
        plugin: String,
        /// What `load_state` said (the state helpers name the type and the field).
        message: String,
    },
    /// A lifecycle step of the swap failed (old `save_state`, new `load_state` or `on_attach`).
    #[error("plugin `{plugin}` was not reloaded: {stage} of the {which} build failed: {message}")]
    Step {
        /// The plugin.
        plugin: String,
        /// `save_state`, `load_state`, `on_attach`.
        stage: &'static str,
        /// "old" or "new".
        which: &'static str,
        /// The panic or error message.
        message: String,
    },
}
