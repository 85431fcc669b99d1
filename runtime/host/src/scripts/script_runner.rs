//! [`ScriptRunner`]: which entities run which script (the host's frame calls them:
//! `host_scripts.rs`).

use std::collections::HashMap;

use onyx_plugin_api::{Component, Script};

use crate::entity_id::to_api;
use crate::world::PluginComponents;

/// The scripts alive per entity (seen `Created`, not yet `Destroyed`).
#[derive(Debug, Default)]
pub struct ScriptRunner {
    pub(crate) live: HashMap<hecs::Entity, Script>,
    /// The world generation the live set belongs to (a new scene starts a new one).
    pub(crate) generation: u64,
}

/// Every entity's [`Script`], decoded; entities whose component does not decode are logged
/// once per frame and skipped.
pub fn scripted_entities(world: &hecs::World) -> Vec<(hecs::Entity, Script)> {
    let mut rows: Vec<(hecs::Entity, Script)> = world
        .query::<(hecs::Entity, &PluginComponents)>()
        .iter()
        .filter_map(|(e, map)| {
            let stored = map.0.get(Script::NAME)?;
            match serde_json::from_slice::<Script>(&stored.bytes) {
                Ok(script) => Some((e, script)),
                Err(error) => {
                    tracing::warn!(entity = %to_api(e), "the Script component does not decode: {error}");
                    None
                }
            }
        })
        .collect();
    rows.sort_by_key(|(e, _)| e.to_bits());
    rows
}
