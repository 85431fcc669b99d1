//! The `--dump-state` JSON: every entity with every component, and the plugins' status.

use base64::Engine as _;
use onyx_plugin_api::{
    BlobFormat, Camera, Collider, Light, MeshRenderer, Name, RigidBody, Transform,
};
use serde_json::{json, Map, Value};

use crate::plugins::{PluginSlot, PluginStatus};
use crate::world::entity_id::to_api;
use crate::world::{HostState, PluginComponents};

/// Version of the dump's layout.
pub const DUMP_FORMAT_VERSION: u32 = 1;

/// The state of the host as JSON:
///
/// ```json
/// { "format": 1, "time": {...}, "plugins": [{"name": "spinner", "status": "running"}],
///   "entities": [{ "id": 4294967296, "name": "cube", "components": {
///       "Name": "cube",
///       "Transform": {"translation": [0,1,0], "rotation": [0,0,0,1], "scale": [1,1,1]},
///       "spinner.spin": {"speed": 1.5},
///       "notes.raw": {"base64": "AAEC"} } }] }
/// ```
///
/// Built-in components are written field by field; plugin components under their name, as
/// their decoded value when stored by serde, else as `{"base64": ...}`.
pub fn dump_state(state: &HostState, plugins: &[PluginSlot]) -> Value {
    let world = &state.world;
    let mut ids: Vec<hecs::Entity> = world.iter().map(|e| e.entity()).collect();
    ids.sort_by_key(|e| e.to_bits());
    let entities: Vec<Value> = ids
        .into_iter()
        .map(|e| {
            let mut components = Map::new();
            let name = world.get::<&Name>(e).ok().map(|n| n.0.clone());
            if let Some(name) = &name {
                components.insert("Name".into(), json!(name));
            }
            if let Ok(t) = world.get::<&Transform>(e) {
                components.insert("Transform".into(), transform_json(&t));
            }
            if let Ok(r) = world.get::<&MeshRenderer>(e) {
                let scene = crate::scene::scene_mesh_renderer(&r, &state.assets);
                components.insert("MeshRenderer".into(), json!(scene));
            }
            if let Ok(c) = world.get::<&Camera>(e) {
                components.insert("Camera".into(), json!(*c));
            }
            if let Ok(l) = world.get::<&Light>(e) {
                components.insert("Light".into(), json!(*l));
            }
            if let Ok(b) = world.get::<&RigidBody>(e) {
                components.insert("RigidBody".into(), json!(*b));
            }
            if let Ok(c) = world.get::<&Collider>(e) {
                let scene = crate::scene::scene_collider(&c, &state.assets);
                components.insert("Collider".into(), json!(scene));
            }
            if let Ok(map) = world.get::<&PluginComponents>(e) {
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

fn transform_json(t: &Transform) -> Value {
    json!({
        "translation": t.translation.to_array(),
        "rotation": t.rotation.to_array(),
        "scale": t.scale.to_array(),
    })
}
