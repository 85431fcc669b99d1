//! [`PlatformEvent`]: events raised by the host itself.

/// Something happened in the host.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum PlatformEvent {
    /// A plugin was loaded and attached.
    PluginLoaded {
        /// The plugin's name.
        plugin: String,
    },
    /// A plugin panicked or returned an error; the host no longer calls it.
    PluginFaulted {
        /// The plugin's name.
        plugin: String,
        /// The lifecycle method that failed (`"on_update"`, …).
        stage: String,
        /// The panic or error message.
        message: String,
    },
    /// A new build of a plugin replaced the running one (hot reload); its state carried over.
    PluginReloaded {
        /// The plugin's name.
        plugin: String,
    },
    /// A new build of a plugin could not replace the running one, which keeps running.
    PluginReloadFailed {
        /// The plugin's name.
        plugin: String,
        /// Why, as a sentence.
        message: String,
    },
    /// A plugin was detached and removed.
    PluginUnloaded {
        /// The plugin's name.
        plugin: String,
    },
    /// An error the host reports to plugins (a failed load, a bad scene file, …).
    Error {
        /// What went wrong, as a sentence.
        message: String,
    },
}
