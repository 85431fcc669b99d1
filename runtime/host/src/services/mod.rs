//! What plugins reach through `Ctx`: the host's implementation of the plugin API's services,
//! for the duration of one call.
//!
//! - `call_context.rs`: [`CallContext`], `HostServices` over the host's state: entities,
//!   components (checked through the one component list), the scene graph, time, input,
//!   events, assets, physics.
//! - `call_context_tools.rs`: its `ToolServices`: entity list, components of an entity,
//!   scenes, plugins, diagnostics, console, play mode, scripts, viewport.

mod call_context;
mod call_context_tools;

pub use call_context::CallContext;
