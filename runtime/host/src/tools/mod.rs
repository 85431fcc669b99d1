//! What the host keeps for the tool services (the editor's needs) between plugin calls.
//!
//! - `tool_state.rs`: [`ToolState`]: diagnostics, the plugin list, play mode, scripts, the
//!   open scene's path.

mod tool_state;

pub use tool_state::ToolState;
