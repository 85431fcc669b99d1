//! What tools (the editor first) read from and ask of the host, through [`Ctx`](crate::Ctx):
//! plain data types, all serde so they can be shown, saved or sent.
//!
//! - `entity_list.rs`: [`EntityList`], every entity with its name, in one call.
//! - `component_entry.rs`: [`ComponentEntry`], one component of an entity as JSON text.
//! - `plugin_info.rs`: [`PluginInfo`], [`PluginState`]: the loaded plugins.
//! - `diagnostics.rs`: [`Diagnostics`], [`PluginTiming`]: what the last frame cost.
//! - `log_line.rs`: [`LogLine`], one line of the host's console.
//! - `play_mode.rs`: [`PlayMode`], edit / playing / paused.
//! - `script.rs`: [`Script`] (the component), [`ScriptCall`], [`ScriptPhase`], [`ScriptInfo`].
//! - `render_overrides.rs`: [`RenderOverrides`], the editor's view switches.
//! - `ray.rs`: [`Ray`], a ray through the viewport.

mod component_entry;
mod diagnostics;
mod entity_list;
mod log_line;
mod play_mode;
mod plugin_info;
mod ray;
mod render_overrides;
mod script;

pub use component_entry::ComponentEntry;
pub use diagnostics::{Diagnostics, PluginTiming, StageTiming};
pub use entity_list::EntityList;
pub use log_line::LogLine;
pub use play_mode::PlayMode;
pub use plugin_info::{PluginInfo, PluginState};
pub use ray::Ray;
pub use render_overrides::RenderOverrides;
pub use script::{Script, ScriptCall, ScriptInfo, ScriptPhase};
