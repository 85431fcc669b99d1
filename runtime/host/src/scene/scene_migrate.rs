//! Older scene formats brought to the current one as they are read, so a file keeps meaning
//! what it meant when it was written.
//!
//! Version 3: colliders scale with their entity (its world scale; see
//! [`Collider`](onyx_plugin_api::Collider)). Files of versions 1 and 2 gave a collider's
//! size and offset in metres whatever the entity's scale: each one on a scaled entity is
//! divided by that scale, so every body keeps the size it had. A sphere or capsule takes the
//! largest scale component (as the physics does); a convex hull or triangle mesh cannot be
//! resized in the file (it names a model), so it is left as it is and named in a warning.

use std::collections::HashMap;

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::ColliderShapeFile;

use super::scene_read::ids_of;
use super::{SceneFile, SCENE_FORMAT_VERSION};

/// The first version whose colliders scale with their entity.
const COLLIDERS_SCALE_FROM: u32 = 3;

/// Brings `scene` to [`SCENE_FORMAT_VERSION`]; returns what could not be kept as it was, one
/// sentence each (the caller names the file).
pub(super) fn migrate(scene: &mut SceneFile) -> Vec<String> {
    let mut warnings = Vec::new();
    if scene.version < COLLIDERS_SCALE_FROM {
        warnings.extend(unscale_colliders(scene));
    }
    scene.version = SCENE_FORMAT_VERSION;
    warnings
}

/// The version 1–2 → 3 step: colliders divided by their entity's world scale.
fn unscale_colliders(scene: &mut SceneFile) -> Vec<String> {
    let scales = world_scales(scene);
    let mut resized = 0usize;
    let mut warnings = Vec::new();
    for (index, entity) in scene.entities.iter_mut().enumerate() {
        let scale = scales[index];
        let Some(collider) = entity.collider.as_mut() else {
            continue;
        };
        if scale == Vec3::ONE || !scale.is_finite() || scale.min_element().abs() <= f32::EPSILON {
            continue;
        }
        let largest = scale.abs().max_element();
        match &mut collider.shape {
            ColliderShapeFile::Sphere { radius } => *radius /= largest,
            ColliderShapeFile::Box { half_extents } => {
                *half_extents = (Vec3::from(*half_extents) / scale.abs()).to_array();
            }
            ColliderShapeFile::Capsule {
                half_height,
                radius,
            } => {
                *half_height /= largest;
                *radius /= largest;
            }
            ColliderShapeFile::Plane => continue,
            ColliderShapeFile::ConvexHull { mesh } | ColliderShapeFile::TriMesh { mesh } => {
                let name = entity.name.as_deref().unwrap_or("unnamed");
                warnings.push(format!(
                    "entity {index} (`{name}`): its collider (the model `{mesh}`) now scales with \
                     the entity ({scale}); the file is from before colliders scaled (version \
                     < {COLLIDERS_SCALE_FROM}), so the body is that much larger — check it and \
                     save the scene"
                ));
                continue;
            }
        }
        collider.offset = (Vec3::from(collider.offset) / scale).to_array();
        resized += 1;
    }
    if resized > 0 {
        tracing::info!(
            resized,
            "scene from before colliders scaled with their entity: {resized} collider(s) on \
             scaled entities resized so each body keeps its size (saving writes version \
             {SCENE_FORMAT_VERSION})"
        );
    }
    warnings
}

/// Each entity's world scale: the product of the scales along its file parent chain (exact
/// for uniform scales and for axes that line up, as scene files mostly have). A broken chain
/// is refused later by the hierarchy check; here it just stops.
fn world_scales(scene: &SceneFile) -> Vec<Vec3> {
    let ids = ids_of(scene);
    let own: Vec<Vec3> = scene
        .entities
        .iter()
        .map(|e| e.transform.map_or(Vec3::ONE, |t| t.scale))
        .collect();
    let parent_of: HashMap<usize, usize> = scene
        .entities
        .iter()
        .enumerate()
        .filter_map(|(i, e)| Some((i, *ids.get(&e.parent?)?)))
        .collect();
    (0..scene.entities.len())
        .map(|index| {
            let mut scale = own[index];
            let mut at = index;
            for _ in 0..scene.entities.len() {
                let Some(&parent) = parent_of.get(&at) else {
                    break;
                };
                scale *= own[parent];
                at = parent;
            }
            scale
        })
        .collect()
}
