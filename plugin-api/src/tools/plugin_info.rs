//! [`PluginInfo`] and [`PluginState`]: the loaded plugins, as tools show them.

use serde::{Deserialize, Serialize};

/// One loaded plugin.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct PluginInfo {
    /// Its name (the crate name).
    pub name: String,
    /// Running, or faulted with the reason.
    pub state: PluginState,
    /// The library file it was loaded from (`None` for an in-process plugin).
    pub path: Option<String>,
    /// How many times a new build replaced it.
    pub reloads: u32,
}

/// Whether the host still calls a plugin.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum PluginState {
    /// Called every frame.
    Running,
    /// Panicked or returned an error; not called again until reloaded.
    Faulted {
        /// The lifecycle method that failed (`on_update`, …).
        stage: String,
        /// The panic or error message.
        message: String,
    },
}
