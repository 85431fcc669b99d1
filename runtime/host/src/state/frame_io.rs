//! [`FrameIo`]: what flows through one frame — events, input, requests, debug lines.

use std::collections::HashMap;

use onyx_plugin_api::host::PluginRequest;
use onyx_plugin_api::{DebugLine, Event, InputState};

/// The default of `HostConfig::max_events_per_frame`.
pub const DEFAULT_MAX_EVENTS_PER_FRAME: u32 = 10_000;

/// A frame's input and output, apart from the world: systems borrow just this to raise an
/// event or read a key.
#[derive(Debug)]
pub struct FrameIo {
    /// Events waiting for the next dispatch.
    pub events: Vec<Event>,
    /// Keyboard and mouse state for this frame.
    pub input: InputState,
    /// Set when a plugin or the window asked to quit.
    pub quit_requested: bool,
    /// While the window's close request is being delivered.
    pub close_requested: bool,
    /// The plugin that kept the window open after a close request (`Ctx::prevent_close`).
    pub close_kept_by: Option<String>,
    /// Plugin changes asked for during the frame, carried out after it.
    pub plugin_requests: Vec<PluginRequest>,
    /// Debug lines plugins drew this frame.
    pub debug_lines: Vec<DebugLine>,
    /// Custom events each plugin sent this frame.
    pub sent: HashMap<String, u32>,
    /// Most custom events one plugin may send per frame.
    pub max_events_per_frame: u32,
    /// A plugin that went over the limit during the call being made (it is faulted when the
    /// call returns).
    pub flooded: Option<String>,
}

impl Default for FrameIo {
    fn default() -> Self {
        Self {
            events: Vec::new(),
            input: InputState::default(),
            quit_requested: false,
            close_requested: false,
            close_kept_by: None,
            plugin_requests: Vec::new(),
            debug_lines: Vec::new(),
            sent: HashMap::new(),
            max_events_per_frame: DEFAULT_MAX_EVENTS_PER_FRAME,
            flooded: None,
        }
    }
}

impl FrameIo {
    /// Counts one custom event from `plugin`; `false` once it is over the limit (the event
    /// is dropped and the plugin marked).
    pub fn count_sent(&mut self, plugin: &str) -> bool {
        let count = match self.sent.get_mut(plugin) {
            Some(count) => count,
            None => self.sent.entry(plugin.to_owned()).or_default(),
        };
        *count += 1;
        if *count <= self.max_events_per_frame {
            return true;
        }
        if self.flooded.is_none() {
            self.flooded = Some(plugin.to_owned());
        }
        false
    }
}
