//! Scripts: behaviours plugins register by name, run for each entity whose
//! [`Script`](onyx_plugin_api::Script) component names them.
//!
//! - `script_registry.rs`: [`ScriptRegistry`], name → plugin and default parameters.
//! - `script_runner.rs`: [`ScriptRunner`], which entities run which script.

mod script_registry;
mod script_runner;

pub use script_registry::ScriptRegistry;
pub use script_runner::{scripted_entities, ScriptRunner};
