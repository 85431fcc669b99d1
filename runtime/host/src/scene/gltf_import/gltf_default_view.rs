//! [`default_view`]: a camera framing a glTF file's meshes and a sun, for a file opened as a
//! scene that has neither.

use std::collections::HashMap;

use onyx_plugin_api::glam::{Mat3, Mat4, Quat, Vec3};
use onyx_plugin_api::{Camera, Light, Transform};

use super::gltf_entities::{node_id, node_transform};
use super::gltf_node_tree::NodeTree;
use crate::scene::SceneEntity;

/// Vertical field of view of the default camera, degrees.
const FOV_Y_DEGREES: f32 = 45.0;
/// Where the default camera looks from, relative to the meshes' centre (front, right, above).
const VIEW_DIRECTION: Vec3 = Vec3::new(0.55, 0.45, 1.0);
/// Room around the meshes' bounding sphere in the default view (1 = touching the frame).
const FRAME_MARGIN: f32 = 1.15;
/// Direction the default sun shines in (as the renderer's own default sun).
const SUN_DIRECTION: Vec3 = Vec3::new(-0.4, -1.0, -0.3);
/// Ambient light added with the default sun (as the renderer's default).
const AMBIENT: f32 = 0.15;

/// Entities to add so the scene can be seen: a camera framing every mesh when the file has no
/// camera, a sun and ambient light when it has no light. Ids start at `first_id`.
/// `root` is the imported root's matrix (the meshes are framed where it puts them).
pub fn default_view(
    document: &gltf::Document,
    tree: &NodeTree,
    root: Mat4,
    first_id: u64,
) -> Vec<SceneEntity> {
    let mut extra = Vec::new();
    let nodes: Vec<gltf::Node<'_>> = document.nodes().collect();
    let in_scene = |f: &dyn Fn(&gltf::Node<'_>) -> bool| {
        tree.order.iter().any(|&i| nodes.get(i).is_some_and(f))
    };
    if !in_scene(&|n| n.camera().is_some()) {
        let (min, max) =
            bounds(&nodes, tree, root).unwrap_or((Vec3::splat(-1.0), Vec3::splat(1.0)));
        let centre = (min + max) * 0.5;
        let radius = ((max - min).length() * 0.5).max(1e-3);
        let fov_y = FOV_Y_DEGREES.to_radians();
        let distance = FRAME_MARGIN * radius / (fov_y * 0.5).sin();
        let eye = centre + VIEW_DIRECTION.normalize() * distance;
        extra.push(SceneEntity {
            id: Some(first_id),
            name: Some("camera".to_owned()),
            transform: Some(Transform {
                translation: eye,
                rotation: looking_at(eye, centre),
                scale: Vec3::ONE,
            }),
            camera: Some(Camera {
                near: (distance - radius).max(radius * 0.01).max(1e-4) * 0.5,
                far: (distance + radius) * 2.0,
                ..Camera::perspective(fov_y)
            }),
            ..SceneEntity::default()
        });
    }
    if !in_scene(&|n| n.light().is_some()) {
        let from = -SUN_DIRECTION.normalize();
        extra.push(SceneEntity {
            id: Some(first_id + 1),
            name: Some("sun".to_owned()),
            transform: Some(Transform::IDENTITY.with_rotation(looking_at(from, Vec3::ZERO))),
            light: Some(Light::sun()),
            ..SceneEntity::default()
        });
        extra.push(SceneEntity {
            id: Some(first_id + 2),
            name: Some("ambient".to_owned()),
            light: Some(Light::Ambient {
                color: [1.0; 3],
                intensity: AMBIENT,
            }),
            transform: Some(Transform::IDENTITY),
            ..SceneEntity::default()
        });
    }
    extra
}

/// The rotation that turns local -Z from `eye` towards `target`, local +Y as near world +Y
/// as it can be.
fn looking_at(eye: Vec3, target: Vec3) -> Quat {
    let back = (eye - target).normalize_or(Vec3::Z);
    let up = if back.abs().y > 0.999 {
        Vec3::Z
    } else {
        Vec3::Y
    };
    let right = up.cross(back).normalize();
    let up = back.cross(right);
    Quat::from_mat3(&Mat3::from_cols(right, up, back)).normalize()
}

/// World-space box around every mesh of the scene under `root`, from the POSITION
/// accessors' `min` and `max` (required by glTF, so no buffer is read); `None` when there is
/// no mesh.
fn bounds(nodes: &[gltf::Node<'_>], tree: &NodeTree, root: Mat4) -> Option<(Vec3, Vec3)> {
    let mut world: HashMap<usize, Mat4> = HashMap::new();
    let mut min = Vec3::splat(f32::INFINITY);
    let mut max = Vec3::splat(f32::NEG_INFINITY);
    for &index in &tree.order {
        let node = nodes.get(index)?;
        let parent = tree
            .parent
            .get(&index)
            .copied()
            .flatten()
            .and_then(|p| world.get(&p).copied())
            .unwrap_or(root);
        let matrix = parent * node_transform(node).matrix();
        world.insert(index, matrix);
        let Some(mesh) = node.mesh() else { continue };
        for primitive in mesh.primitives() {
            let b = primitive.bounding_box();
            let (lo, hi) = (Vec3::from(b.min), Vec3::from(b.max));
            if !(lo.is_finite() && hi.is_finite()) {
                continue;
            }
            for corner in 0..8 {
                let p = Vec3::new(
                    if corner & 1 == 0 { lo.x } else { hi.x },
                    if corner & 2 == 0 { lo.y } else { hi.y },
                    if corner & 4 == 0 { lo.z } else { hi.z },
                );
                let w = matrix.transform_point3(p);
                min = min.min(w);
                max = max.max(w);
            }
        }
    }
    (min.is_finite() && max.is_finite()).then_some((min, max))
}

/// The file id after every node's (for entities the import adds).
pub fn first_free_id(document: &gltf::Document) -> u64 {
    node_id(document.nodes().len())
}
