//! [`HostConfig`]: how a host is set up.

use crate::clock::ClockSettings;
use crate::plugins::PluginSearchPath;

/// Everything a [`Host`](crate::Host) is built from.
#[derive(Clone, Debug)]
pub struct HostConfig {
    /// The fixed-step clock.
    pub clock: ClockSettings,
    /// Settings handed to plugins in `AttachInfo`: `(plugin, key, value)`.
    pub plugin_settings: Vec<(String, String, String)>,
    /// Where plugins given by name are looked up.
    pub search_path: PluginSearchPath,
}

impl Default for HostConfig {
    fn default() -> Self {
        Self {
            clock: ClockSettings::default(),
            plugin_settings: Vec::new(),
            search_path: PluginSearchPath::from_env(),
        }
    }
}

impl HostConfig {
    /// Returns this config with `fixed_hz` fixed steps per second.
    #[must_use]
    pub fn fixed_hz(mut self, hz: f64) -> Self {
        self.clock.fixed_hz = hz;
        self
    }

    /// Returns this config with a setting for `plugin`.
    #[must_use]
    pub fn setting(
        mut self,
        plugin: impl Into<String>,
        key: impl Into<String>,
        value: impl Into<String>,
    ) -> Self {
        self.plugin_settings
            .push((plugin.into(), key.into(), value.into()));
        self
    }
}
