//! Spawning a scene file's entities into a world: every value checked, the parents resolved,
//! and nothing left behind on error.

use std::collections::HashMap;
use std::path::Path;

use base64::Engine as _;
use onyx_plugin_api::{AnimationId, BlobFormat, BuiltinValue, Entity, FileRefs, MeshId, TextureId};

use super::scene_read::ids_of;
use super::{SceneComponent, SceneEntity, SceneError, SceneFile};
use crate::assets::AssetRegistry;
use crate::entity_id::to_api;
use crate::world::{builtin_storage, PluginComponents, StoredBlob, WorldRefs};

/// [`FileRefs`] while a scene spawns: assets registered in the host's registry (found
/// relative to the scene file), file ids resolved to the entities spawned for them.
struct SpawnRefs<'a> {
    assets: &'a mut AssetRegistry,
    entities: &'a HashMap<u64, hecs::Entity>,
    scene_dir: &'a Path,
}

impl FileRefs for SpawnRefs<'_> {
    fn mesh(&mut self, path: &str) -> MeshId {
        let path = self.assets.find_beside(self.scene_dir, Path::new(path));
        self.assets.mesh(&path)
    }

    fn texture(&mut self, path: &str) -> TextureId {
        let path = self.assets.find_beside(self.scene_dir, Path::new(path));
        self.assets.texture(&path)
    }

    fn animation(&mut self, path: &str) -> AnimationId {
        let path = self.assets.find_beside(self.scene_dir, Path::new(path));
        self.assets.animation(&path)
    }

    fn entity(&self, file_id: u64) -> Option<Entity> {
        self.entities.get(&file_id).map(|e| to_api(*e))
    }
}

/// The plugin components of a scene entity, decoded.
fn plugin_components(entity: &SceneEntity) -> Result<PluginComponents, String> {
    let mut blobs = PluginComponents::default();
    for (name, component) in &entity.components {
        let stored = match component {
            SceneComponent::Json(value) => StoredBlob {
                format: BlobFormat::Json,
                bytes: serde_json::to_vec(value).map_err(|e| format!("component `{name}`: {e}"))?,
            },
            SceneComponent::Raw(text) => StoredBlob {
                format: BlobFormat::Raw,
                bytes: base64::engine::general_purpose::STANDARD
                    .decode(text)
                    .map_err(|e| format!("component `{name}` is not valid base64: {e}"))?,
            },
        };
        blobs.0.insert(name.clone(), stored);
    }
    Ok(blobs)
}

/// Spawns every entity of `scene` (parsed by [`parse_scene`](super::parse_scene), so its
/// scene graph is sound) into `ecs`. Every value is checked first: on error `ecs` holds what
/// it held before. Returns the number of entities spawned. The caller tells the world's
/// scene graph that entities arrived.
pub fn spawn_scene(
    ecs: &mut hecs::World,
    assets: &mut AssetRegistry,
    scene: &SceneFile,
    path: &Path,
) -> Result<usize, SceneError> {
    spawn_scene_entities(ecs, assets, scene, path).map(|spawned| spawned.len())
}

/// [`spawn_scene`], returning the entities spawned in file order.
pub fn spawn_scene_entities(
    ecs: &mut hecs::World,
    assets: &mut AssetRegistry,
    scene: &SceneFile,
    path: &Path,
) -> Result<Vec<hecs::Entity>, SceneError> {
    let spawned: Vec<hecs::Entity> = scene.entities.iter().map(|_| ecs.spawn(())).collect();
    let by_id: HashMap<u64, hecs::Entity> = ids_of(scene)
        .into_iter()
        .map(|(id, index)| (id, spawned[index]))
        .collect();
    let prepared = prepare(ecs, assets, scene, &by_id, path);
    let prepared = match prepared {
        Ok(prepared) => prepared,
        Err(error) => {
            for e in spawned {
                let _ = ecs.despawn(e);
            }
            return Err(error);
        }
    };
    // The models these settings are for load when first drawn or collided, after this.
    let scene_dir = path.parent().unwrap_or(Path::new(""));
    for (model, settings) in &scene.imports {
        if let Ok(settings) = settings.settings() {
            let found = assets.find_beside(scene_dir, Path::new(model));
            assets.set_import_settings(&found, settings);
        }
    }
    let mut builder = hecs::EntityBuilder::new();
    for (e, (builtins, plugin)) in spawned.iter().zip(prepared) {
        for value in &builtins {
            builtin_storage::add_to(&mut builder, value);
        }
        if !plugin.0.is_empty() {
            builder.add(plugin);
        }
        let _ = ecs.insert(*e, builder.build());
    }
    Ok(spawned)
}

type Prepared = Vec<(Vec<BuiltinValue>, PluginComponents)>;

/// Every entity's components, read and checked.
fn prepare(
    ecs: &hecs::World,
    assets: &mut AssetRegistry,
    scene: &SceneFile,
    by_id: &HashMap<u64, hecs::Entity>,
    path: &Path,
) -> Result<Prepared, SceneError> {
    let mut prepared = Vec::with_capacity(scene.entities.len());
    for (index, entity) in scene.entities.iter().enumerate() {
        let invalid = |message: String| SceneError::InvalidEntity {
            path: path.to_path_buf(),
            index,
            name: entity.name.clone(),
            message,
        };
        let mut refs = SpawnRefs {
            assets: &mut *assets,
            entities: by_id,
            scene_dir: path.parent().unwrap_or(Path::new("")),
        };
        let builtins = entity
            .builtins(&mut refs)
            .map_err(|(id, e)| invalid(format!("its {} {e}", id.scene_key())))?;
        let checks = WorldRefs {
            ecs,
            assets,
            file_ids: None,
        };
        for value in &builtins {
            value
                .validate(&checks)
                .map_err(|e| invalid(format!("its {} {e}", value.id().scene_key())))?;
        }
        let plugin = plugin_components(entity).map_err(invalid)?;
        prepared.push((builtins, plugin));
    }
    Ok(prepared)
}
