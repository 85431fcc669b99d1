//! [`PluginStatus`]: whether the host still calls a plugin.

use crate::stage::Stage;

/// Whether a plugin is running or has faulted.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PluginStatus {
    /// Called every frame.
    Running,
    /// Panicked or failed; never called again (a reload can revive it).
    Faulted {
        /// Where it failed.
        stage: Stage,
        /// The panic or error message.
        message: String,
    },
}

impl PluginStatus {
    /// Whether the plugin has faulted.
    pub fn is_faulted(&self) -> bool {
        matches!(self, PluginStatus::Faulted { .. })
    }
}
