//! [`FrameIo`]: what flows through one frame — events, input, requests, debug lines.

use onyx_plugin_api::host::PluginRequest;
use onyx_plugin_api::{DebugLine, Event, InputState};

/// A frame's input and output, apart from the world: systems borrow just this to raise an
/// event or read a key.
#[derive(Debug, Default)]
pub struct FrameIo {
    /// Events waiting for the next dispatch.
    pub events: Vec<Event>,
    /// Keyboard and mouse state for this frame.
    pub input: InputState,
    /// Set when a plugin or the window asked to quit.
    pub quit_requested: bool,
    /// Plugin changes asked for during the frame, carried out after it.
    pub plugin_requests: Vec<PluginRequest>,
    /// Debug lines plugins drew this frame.
    pub debug_lines: Vec<DebugLine>,
}
