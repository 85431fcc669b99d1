//! Reading a scene into the world, and writing the world to a scene, atomically.

use std::io::Write;
use std::path::Path;

use base64::Engine as _;
use onyx_plugin_api::{BlobFormat, Name, Transform};

use super::{SceneComponent, SceneEntity, SceneError, SceneFile, SCENE_FORMAT_VERSION};
use crate::world::{PluginComponents, StoredBlob};

/// Parses scene text; `path` is only used in error messages.
pub fn parse_scene(text: &str, path: &Path) -> Result<SceneFile, SceneError> {
    let scene: SceneFile = ron::from_str(text).map_err(|e| SceneError::Parse {
        path: path.to_path_buf(),
        line: e.span.start.line,
        column: e.span.start.col,
        message: e.code.to_string(),
    })?;
    if scene.version != SCENE_FORMAT_VERSION {
        return Err(SceneError::UnsupportedVersion {
            path: path.to_path_buf(),
            found: scene.version,
            supported: SCENE_FORMAT_VERSION,
        });
    }
    Ok(scene)
}

/// Reads and parses the scene at `path`.
pub fn read_scene(path: &Path) -> Result<SceneFile, SceneError> {
    let text = std::fs::read_to_string(path).map_err(|source| SceneError::Io {
        action: "read",
        path: path.to_path_buf(),
        source,
    })?;
    parse_scene(&text, path)
}

/// The components of one scene entity, checked and decoded.
struct Prepared {
    name: Option<Name>,
    transform: Option<Transform>,
    blobs: PluginComponents,
}

fn prepare(entity: &SceneEntity, index: usize, path: &Path) -> Result<Prepared, SceneError> {
    let invalid = |message: String| SceneError::InvalidEntity {
        path: path.to_path_buf(),
        index,
        message,
    };
    if let Some(t) = &entity.transform {
        if !t.is_finite() {
            return Err(invalid("its transform holds NaN or infinity".into()));
        }
    }
    let mut blobs = PluginComponents::default();
    for (name, component) in &entity.components {
        let stored = match component {
            SceneComponent::Json(value) => StoredBlob {
                format: BlobFormat::Json,
                bytes: serde_json::to_vec(value)
                    .map_err(|e| invalid(format!("component `{name}`: {e}")))?,
            },
            SceneComponent::Raw(text) => StoredBlob {
                format: BlobFormat::Raw,
                bytes: base64::engine::general_purpose::STANDARD
                    .decode(text)
                    .map_err(|e| invalid(format!("component `{name}` is not valid base64: {e}")))?,
            },
        };
        blobs.0.insert(name.clone(), stored);
    }
    Ok(Prepared {
        name: entity.name.clone().map(Name),
        transform: entity.transform,
        blobs,
    })
}

/// Spawns every entity of `scene` into `world`. All entities are checked first: on error the
/// world is unchanged. Returns the number of entities spawned.
pub fn spawn_scene(
    world: &mut hecs::World,
    scene: &SceneFile,
    path: &Path,
) -> Result<usize, SceneError> {
    let prepared = scene
        .entities
        .iter()
        .enumerate()
        .map(|(i, e)| prepare(e, i, path))
        .collect::<Result<Vec<_>, _>>()?;
    let count = prepared.len();
    for p in prepared {
        let e = world.spawn(());
        if let Some(name) = p.name {
            let _ = world.insert_one(e, name);
        }
        if let Some(t) = p.transform {
            let _ = world.insert_one(e, t);
        }
        if !p.blobs.0.is_empty() {
            let _ = world.insert_one(e, p.blobs);
        }
    }
    Ok(count)
}

/// The world as a scene file, entities in id order.
pub fn scene_from_world(world: &hecs::World) -> SceneFile {
    let mut ids: Vec<hecs::Entity> = world.iter().map(|e| e.entity()).collect();
    ids.sort_by_key(|e| e.to_bits());
    let entities = ids
        .into_iter()
        .map(|e| {
            let name = world.get::<&Name>(e).ok().map(|n| n.0.clone());
            let transform = world.get::<&Transform>(e).ok().map(|t| *t);
            let components = world
                .get::<&PluginComponents>(e)
                .map(|map| {
                    map.0
                        .iter()
                        .map(|(k, blob)| (k.clone(), scene_component(blob)))
                        .collect()
                })
                .unwrap_or_default();
            SceneEntity {
                name,
                transform,
                components,
            }
        })
        .collect();
    SceneFile {
        version: SCENE_FORMAT_VERSION,
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

/// Writes `scene` to `path` atomically: to a temporary file in the same directory, flushed
/// to disk, then renamed over `path`. A crash or error leaves the previous file intact.
pub fn write_scene(scene: &SceneFile, path: &Path) -> Result<(), SceneError> {
    let text =
        ron::ser::to_string_pretty(scene, ron::ser::PrettyConfig::default()).map_err(|e| {
            SceneError::Serialize {
                message: e.to_string(),
            }
        })?;
    write_atomically(path, text.as_bytes()).map_err(|source| SceneError::Io {
        action: "write",
        path: path.to_path_buf(),
        source,
    })
}

/// Writes `bytes` to `path` through a temporary file and a rename.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let mut tmp = tempfile::NamedTempFile::new_in(dir)?;
    tmp.write_all(bytes)?;
    tmp.as_file().sync_all()?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}
