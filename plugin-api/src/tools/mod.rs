//! What tools (the editor first) read from and ask of the host, through [`Ctx`](crate::Ctx):
//! plain data types.
//!
//! - `entity_list.rs`: [`EntityList`], every entity with its name and parent, in one call.
//! - `component_value.rs`: [`ComponentValue`], [`ComponentKey`], [`PluginValue`]: one
//!   component of an entity, typed.
//! - `plugin_info.rs`: [`PluginInfo`], [`PluginState`]: the loaded plugins.
//! - `diagnostics.rs`: [`Diagnostics`], [`PluginTiming`]: what the last frame cost.
//! - `log_line.rs`: [`LogLine`], one line of the host's console.
//! - `play_mode.rs`: [`PlayMode`], edit / playing / paused.
//! - `script.rs`: [`Script`] (the component), [`ScriptCall`], [`ScriptPhase`], [`ScriptInfo`].
//! - `render_overrides.rs`: [`RenderOverrides`], the editor's view switches.
//! - `ray.rs`: [`Ray`], a ray through the viewport.
//! - `bounds.rs`: [`Bounds`], the box an entity shows, in its own frame.

mod bounds;
mod component_value;
mod diagnostics;
mod entity_list;
mod log_line;
mod play_mode;
mod plugin_info;
mod ray;
mod render_overrides;
mod script;

pub use bounds::Bounds;
pub use component_value::{ComponentKey, ComponentValue, PluginValue};
pub use diagnostics::{Diagnostics, PluginTiming, StageTiming};
pub use entity_list::EntityList;
pub use log_line::LogLine;
pub use play_mode::PlayMode;
pub use plugin_info::{PluginInfo, PluginState};
pub use ray::Ray;
pub use render_overrides::RenderOverrides;
pub use script::{Script, ScriptCall, ScriptInfo, ScriptPhase};
