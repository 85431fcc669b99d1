//! The world plugins see: hecs plus the host's own component types.
//!
//! - `plugin_components.rs`: [`PluginComponents`], named plugin data per entity.
//! - `entity_id.rs`: API ↔ hecs entity handles.
//! - `call_context.rs`: [`CallContext`], the `HostServices` a plugin call is served by;
//!   `call_context_tools.rs`: its tool services; `component_json.rs`: components by type
//!   name as JSON (the inspector's read and write).
//! - `tool_state.rs`: [`ToolState`], what the tool services keep between calls.

mod call_context;
mod call_context_tools;
mod component_json;
pub mod entity_id;
mod plugin_components;
mod tool_state;

pub use call_context::{CallContext, HostState};
pub use plugin_components::{PluginComponents, StoredBlob};
pub use tool_state::ToolState;
