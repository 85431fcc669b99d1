//! The `--dump-state` JSON: every entity with every component, and the plugins' status.

use base64::Engine as _;
use onyx_plugin_api::{BlobFormat, GlobalTransform, Name, Transform};
use serde_json::{json, Map, Value};

use crate::entity_id::to_api;
use crate::plugins::{PluginSlot, PluginStatus};
use crate::state::HostState;
use crate::world::{builtin_storage, PluginComponents};

/// Version of the dump's layout. 2: `Parent` and `GlobalTransform`.
pub const DUMP_FORMAT_VERSION: u32 = 2;

/// The state of the host as JSON:
///
/// ```json
/// { "format": 2, "time": {...}, "plugins": [{"name": "spinner", "status": "running"}],
///   "entities": [{ "id": 4294967296, "name": "cube", "components": {
///       "Name": "cube",
///       "Transform": {"translation": [0,1,0], "rotation": [0,0,0,1], "scale": [1,1,1]},
///       "Parent": 4294967297,
///       "GlobalTransform": {"translation": [0,3,0], "rotation": [0,0,0,1], "scale": [1,1,1]},
///       "spinner.spin": {"speed": 1.5},
///       "notes.raw": {"base64": "AAEC"} } }] }
/// ```
///
/// Built-in components are written field by field in their scene-file form (meshes and
/// textures by path; `Parent` as the parent's `id`); every entity with a `Transform` also
/// shows its world pose as `GlobalTransform` (same fields; the nearest unsheared pose); plugin
/// components under their name, as their decoded value when stored by serde, else as
/// `{"base64": ...}`.
pub fn dump_state(state: &HostState, plugins: &[PluginSlot]) -> Value {
    let world = &state.world;
    let ecs = &world.ecs;
    let refs = world.refs();
    let mut ids: Vec<hecs::Entity> = ecs.iter().map(|e| e.entity()).collect();
    ids.sort_by_key(|e| e.to_bits());
    let entities: Vec<Value> = ids
        .into_iter()
        .map(|e| {
            let mut components = Map::new();
            for value in builtin_storage::all_of(ecs, e) {
                components.insert(value.name().into(), value.file_json(&refs));
            }
            if ecs.satisfies::<&Transform>(e) {
                let pose = GlobalTransform(world.world_pose(e)).to_transform();
                components.insert("GlobalTransform".into(), json!(pose));
            }
            if let Ok(map) = ecs.get::<&PluginComponents>(e) {
                for (key, blob) in &map.0 {
                    let value = match blob.format {
                        BlobFormat::Json => serde_json::from_slice(&blob.bytes).ok(),
                        BlobFormat::Raw => None,
                    };
                    let value = value.unwrap_or_else(|| {
                        json!({ "base64": base64::engine::general_purpose::STANDARD.encode(&blob.bytes) })
                    });
                    components.insert(key.clone(), value);
                }
            }
            let name = ecs.get::<&Name>(e).ok().map(|n| n.0.clone());
            json!({
                "id": to_api(e).to_bits(),
                "name": name,
                "components": components,
            })
        })
        .collect();
    let plugins: Vec<Value> = plugins
        .iter()
        .map(|p| match p.status() {
            PluginStatus::Running => json!({ "name": p.name(), "status": "running" }),
            PluginStatus::Faulted { stage, message } => json!({
                "name": p.name(), "status": "faulted", "stage": stage.as_str(), "message": message,
            }),
        })
        .collect();
    let time = state.clock.time();
    json!({
        "format": DUMP_FORMAT_VERSION,
        "time": {
            "frame": time.frame, "ticks": time.ticks, "total": time.total,
            "fixed_delta": time.fixed_delta, "alpha": time.alpha, "paused": time.paused,
        },
        "plugins": plugins,
        "entities": entities,
    })
}
