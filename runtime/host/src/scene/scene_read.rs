//! Reading a scene file: RON parsed with line and column errors, its version and physics
//! checked, and its scene graph checked (unique ids, parents that exist, no cycles).

use onyx_render::ImportSettings;
use std::collections::HashMap;
use std::path::Path;

use super::{SceneError, SceneFile, OLDEST_SCENE_FORMAT_VERSION, SCENE_FORMAT_VERSION};

/// Parses scene text; `path` is only used in error messages.
pub fn parse_scene(text: &str, path: &Path) -> Result<SceneFile, SceneError> {
    let scene: SceneFile = ron::from_str(text).map_err(|e| SceneError::Parse {
        path: path.to_path_buf(),
        line: e.span.start.line,
        column: e.span.start.col,
        message: e.code.to_string(),
    })?;
    if !(OLDEST_SCENE_FORMAT_VERSION..=SCENE_FORMAT_VERSION).contains(&scene.version) {
        return Err(SceneError::UnsupportedVersion {
            path: path.to_path_buf(),
            found: scene.version,
            oldest: OLDEST_SCENE_FORMAT_VERSION,
            newest: SCENE_FORMAT_VERSION,
        });
    }
    if let Some(physics) = &scene.physics {
        physics
            .validate()
            .map_err(|message| SceneError::InvalidPhysics {
                path: path.to_path_buf(),
                message,
            })?;
    }
    for (model, settings) in &scene.imports {
        settings
            .settings()
            .map_err(|message| SceneError::InvalidImport {
                path: path.to_path_buf(),
                model: model.clone(),
                message,
            })?;
    }
    check_hierarchy(&scene, path)?;
    let mut scene = scene;
    for warning in super::scene_migrate::migrate(&mut scene) {
        tracing::warn!("`{}`: {warning}", path.display());
    }
    Ok(scene)
}

/// Reads and parses the scene at `path`: a scene file, or a glTF file (`.gltf`, `.glb`)
/// whose node tree becomes the scene, with a framing camera and a sun when it has none (each
/// feature the import leaves out logged once), imported with the default settings.
pub fn read_scene(path: &Path) -> Result<SceneFile, SceneError> {
    read_scene_with(path, &ImportSettings::default())
}

/// [`read_scene`], a glTF file imported with `gltf` (its scale and up axis on the root, see
/// [`import_gltf_scene`](super::import_gltf_scene)); a scene file's own `imports` table
/// gives its models' settings, so `gltf` does not touch it.
pub fn read_scene_with(path: &Path, gltf: &ImportSettings) -> Result<SceneFile, SceneError> {
    if super::is_gltf_scene(path) {
        let imported = super::import_gltf_scene(path, true, gltf)?;
        for warning in &imported.warnings {
            tracing::warn!("`{}`: {warning}", path.display());
        }
        return Ok(imported.scene);
    }
    let text = std::fs::read_to_string(path).map_err(|cause| SceneError::Io {
        action: "read",
        path: path.to_path_buf(),
        cause,
    })?;
    parse_scene(&text, path)
}

/// The index of the entity each file id names.
pub(super) fn ids_of(scene: &SceneFile) -> HashMap<u64, usize> {
    scene
        .entities
        .iter()
        .enumerate()
        .filter_map(|(i, e)| e.id.map(|id| (id, i)))
        .collect()
}

/// Refuses ids used twice, parents naming no entity and parent chains that loop, naming the
/// entity at fault.
fn check_hierarchy(scene: &SceneFile, path: &Path) -> Result<(), SceneError> {
    let invalid = |index: usize, message: String| SceneError::InvalidEntity {
        path: path.to_path_buf(),
        index,
        name: scene.entities[index].name.clone(),
        message,
    };
    let mut ids: HashMap<u64, usize> = HashMap::new();
    for (i, entity) in scene.entities.iter().enumerate() {
        if let Some(id) = entity.id {
            if let Some(first) = ids.insert(id, i) {
                return Err(invalid(
                    i,
                    format!("its id {id} is already the id of entity #{first}"),
                ));
            }
        }
    }
    let parent_of = |i: usize| -> Result<Option<usize>, SceneError> {
        match scene.entities[i].parent {
            None => Ok(None),
            Some(id) => ids.get(&id).copied().map(Some).ok_or_else(|| {
                invalid(
                    i,
                    format!("its parent is id {id}, which no entity of the file has"),
                )
            }),
        }
    };
    // 0: not visited, 1: on the chain being followed, 2: known to reach a root.
    let mut state = vec![0u8; scene.entities.len()];
    for start in 0..scene.entities.len() {
        let mut chain = Vec::new();
        let mut at = Some(start);
        while let Some(i) = at {
            match state[i] {
                2 => break,
                1 => {
                    let names: Vec<String> = chain
                        .iter()
                        .skip_while(|&&c| c != i)
                        .map(|&c| format!("#{c}"))
                        .collect();
                    return Err(invalid(
                        i,
                        format!(
                            "its parent chain loops back to it ({} → #{i}): a scene graph has no cycles",
                            names.join(" → ")
                        ),
                    ));
                }
                _ => {}
            }
            state[i] = 1;
            chain.push(i);
            at = parent_of(i)?;
        }
        for i in chain {
            state[i] = 2;
        }
    }
    Ok(())
}
