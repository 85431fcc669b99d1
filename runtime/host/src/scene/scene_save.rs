//! Saving a world as a scene file: every entity with its components in file form, parents by
//! file-local id, written atomically.

use std::collections::HashMap;
use std::path::Path;

use base64::Engine as _;
use onyx_plugin_api::BlobFormat;

use super::{SceneComponent, SceneEntity, SceneError, SceneFile, SCENE_FORMAT_VERSION};
use crate::world::{builtin_storage, PluginComponents, StoredBlob, WorldRefs, WorldState};

/// The world as a scene file, entities in id order. Entities that are parents get an `id`
/// (their index in the file), which their children's `parent` names.
pub fn scene_from_world(world: &WorldState) -> SceneFile {
    let ecs = &world.ecs;
    let mut order: Vec<hecs::Entity> = ecs.iter().map(|e| e.entity()).collect();
    order.sort_by_key(|e| e.to_bits());
    let index: HashMap<hecs::Entity, u64> = order
        .iter()
        .enumerate()
        .map(|(i, e)| (*e, i as u64))
        .collect();
    let parents: HashMap<hecs::Entity, u64> = ecs
        .query::<&onyx_plugin_api::Parent>()
        .iter()
        .filter_map(|p| crate::entity_id::to_hecs(p.0))
        .filter_map(|p| index.get(&p).map(|i| (p, *i)))
        .collect();
    let refs = WorldRefs {
        ecs,
        assets: &world.assets,
        file_ids: Some(&parents),
    };
    let entities = order
        .into_iter()
        .map(|e| {
            let mut entity = SceneEntity {
                id: parents.get(&e).copied(),
                ..SceneEntity::default()
            };
            for value in builtin_storage::all_of(ecs, e) {
                entity.set_builtin(&value, &refs);
            }
            if let Ok(map) = ecs.get::<&PluginComponents>(e) {
                entity.components = map
                    .0
                    .iter()
                    .map(|(k, blob)| (k.clone(), scene_component(blob)))
                    .collect();
            }
            entity
        })
        .collect();
    SceneFile {
        version: SCENE_FORMAT_VERSION,
        physics: None,
        imports: world
            .assets
            .all_import_settings()
            .map(|(path, settings)| {
                (
                    path.display().to_string(),
                    super::ImportSettingsFile::from_settings(settings),
                )
            })
            .collect(),
        entities,
    }
}

fn scene_component(blob: &StoredBlob) -> SceneComponent {
    let raw = || SceneComponent::Raw(base64::engine::general_purpose::STANDARD.encode(&blob.bytes));
    match blob.format {
        BlobFormat::Json => serde_json::from_slice(&blob.bytes)
            .map(SceneComponent::Json)
            .unwrap_or_else(|_| raw()),
        BlobFormat::Raw => raw(),
    }
}

/// Writes `scene` to `path` atomically: a crash or error leaves the previous file intact.
pub fn write_scene(scene: &SceneFile, path: &Path) -> Result<(), SceneError> {
    let text =
        ron::ser::to_string_pretty(scene, ron::ser::PrettyConfig::default()).map_err(|e| {
            SceneError::Serialize {
                message: e.to_string(),
            }
        })?;
    crate::fs::write_atomically(path, text.as_bytes()).map_err(|cause| SceneError::Io {
        action: "write",
        path: path.to_path_buf(),
        cause,
    })
}
