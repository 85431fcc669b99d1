//! [`HostConfig`]: how a host is set up.

use crate::clock::ClockSettings;
use crate::plugins::PluginSearchPath;
pub use crate::state::DEFAULT_MAX_EVENTS_PER_FRAME;

/// Everything a [`Host`](crate::Host) is built from.
#[derive(Clone, Debug)]
pub struct HostConfig {
    /// The fixed-step clock.
    pub clock: ClockSettings,
    /// Settings handed to plugins in `AttachInfo`: `(plugin, key, value)`.
    pub plugin_settings: Vec<(String, String, String)>,
    /// Where plugins given by name are looked up.
    pub search_path: PluginSearchPath,
    /// The folder relative model and texture paths start from (default: the working
    /// directory).
    pub asset_root: std::path::PathBuf,
    /// Most custom events one plugin may send in one frame (default
    /// [`DEFAULT_MAX_EVENTS_PER_FRAME`]). A plugin that sends more is faulted and the rest
    /// are dropped: an event answered with two would otherwise fill memory until the host
    /// aborts. Too low refuses a plugin's legitimate bursts; too high lets a flood grow the
    /// queue (each event is kept until the next frame).
    pub max_events_per_frame: u32,
    /// Keep every old build's library mapped after a hot reload or an unload (default
    /// `false`: an old image is unmapped once nothing from it can run, see
    /// `plugins/image_unload.rs`). Set it for plugins that hand callbacks to a C library or
    /// start threads outside Rust's std and cannot take them back in `on_detach`; memory
    /// then grows by one library image per swap.
    pub keep_old_builds: bool,
}

impl Default for HostConfig {
    fn default() -> Self {
        Self {
            clock: ClockSettings::default(),
            plugin_settings: Vec::new(),
            search_path: PluginSearchPath::from_env(),
            asset_root: std::path::PathBuf::new(),
            max_events_per_frame: DEFAULT_MAX_EVENTS_PER_FRAME,
            keep_old_builds: false,
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

    /// Returns this config with relative asset paths starting from `root`.
    #[must_use]
    pub fn asset_root(mut self, root: impl Into<std::path::PathBuf>) -> Self {
        self.asset_root = root.into();
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
