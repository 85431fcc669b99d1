//! The world plugins see: hecs plus the host's own component types.
//!
//! - `plugin_components.rs`: [`PluginComponents`], named plugin data per entity.
//! - `entity_id.rs`: API ↔ hecs entity handles.
//! - `call_context.rs`: [`CallContext`], the `HostServices` a plugin call is served by.

mod call_context;
pub mod entity_id;
mod plugin_components;

pub use call_context::{CallContext, HostState};
pub use plugin_components::{PluginComponents, StoredBlob};
