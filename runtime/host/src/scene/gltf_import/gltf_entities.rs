//! [`gltf_entities`]: a glTF file's nodes as scene-file entities under one root: transforms,
//! parents, names, one mesh renderer per mesh (naming that mesh of the file), cameras and
//! lights.

use std::path::Path;

use onyx_plugin_api::glam::{Mat4, Quat, Vec3};
use onyx_plugin_api::{
    AnimatorFile, Camera, Light, MeshRendererFile, Projection, ShadingMode, Transform,
};
use onyx_render::{ImportSettings, SubAsset, UpAxis};

use super::gltf_node_tree::NodeTree;
use crate::scene::SceneEntity;

/// The file id of the root entity the nodes hang under.
pub const ROOT_ID: u64 = 1;

/// The file id of node `index`'s entity.
pub fn node_id(index: usize) -> u64 {
    ROOT_ID + 1 + index as u64
}

/// Far plane of a perspective camera the file leaves infinite, in multiples of its near
/// plane (wgpu's depth has no infinite projection here).
const INFINITE_FAR_OVER_NEAR: f32 = 100_000.0;
/// Near plane given to an orthographic camera whose file says 0 (Onyx needs > 0), metres.
const MIN_NEAR: f32 = 1e-3;
/// Illuminance (lux) at which a point light without a range is taken to have faded out:
/// its range is `sqrt(intensity / this)`.
const FADED_LUX: f32 = 0.01;
/// Range of a point light whose intensity is not positive, metres.
const FALLBACK_RANGE: f32 = 10.0;
/// Onyx intensity per candela of a point or spot light. Onyx has no exposure: its point
/// lights fall off as `intensity / (1 + d²)` onto a surface drawn at full colour by 1, so
/// 100 cd one metre away lights like the default sun. Too high blows lamps out to white
/// (Blender's exports give 15..200 cd); too low leaves them dark.
pub const ONYX_PER_CANDELA: f32 = 0.01;

/// The file's own name, as its pieces' mesh renderers and its `imports` entry write it.
pub fn file_name(path: &Path) -> &Path {
    Path::new(path.file_name().unwrap_or(path.as_os_str()))
}

/// The imported root's transform: at the origin, turned so the file's up axis is +Y (as
/// [`UpAxis::to_y_up`]) and scaled uniformly, so the node tree comes in as one piece.
pub fn root_transform(settings: &ImportSettings) -> Transform {
    let rotation = match settings.up_axis {
        UpAxis::Y => Quat::IDENTITY,
        UpAxis::Z => Quat::from_rotation_x(-std::f32::consts::FRAC_PI_2),
    };
    Transform {
        translation: Vec3::ZERO,
        rotation,
        scale: Vec3::splat(settings.scale),
    }
}

/// The root (named after the file, with `root` as its transform, with an animator playing
/// all of the file's animations when it has any) then one entity per node of `tree`, parents
/// before children. Mesh renderers name `FILE#mesh/N` with `FILE` as written beside the
/// scene (the file's own name): spawned with the glTF path as the scene path, that is the
/// file itself.
pub fn gltf_entities(
    document: &gltf::Document,
    tree: &NodeTree,
    path: &Path,
    root: Transform,
) -> Vec<SceneEntity> {
    let file_name = file_name(path);
    let root_name = path
        .file_stem()
        .map_or_else(|| "glTF".to_owned(), |s| s.to_string_lossy().into_owned());
    // The root plays every animation of the file, looping, from the start.
    let animator = (document.animations().next().is_some()).then(|| AnimatorFile {
        clip: file_name.to_string_lossy().into_owned(),
        time: 0.0,
        speed: 1.0,
        playing: true,
        looping: true,
    });
    let mut entities = vec![SceneEntity {
        id: Some(ROOT_ID),
        name: Some(root_name),
        transform: Some(root),
        animator,
        ..SceneEntity::default()
    }];
    let nodes: Vec<gltf::Node<'_>> = document.nodes().collect();
    let mut first_camera = true;
    for &index in &tree.order {
        let Some(node) = nodes.get(index) else {
            continue;
        };
        let parent = tree
            .parent
            .get(&index)
            .copied()
            .flatten()
            .map_or(ROOT_ID, node_id);
        let mut entity = SceneEntity {
            id: Some(node_id(index)),
            name: tree.names.get(&index).cloned(),
            parent: Some(parent),
            transform: Some(node_transform(node)),
            ..SceneEntity::default()
        };
        if let Some(mesh) = node.mesh().filter(has_triangles) {
            entity.mesh_renderer = Some(MeshRendererFile {
                mesh: SubAsset::Mesh(mesh.index())
                    .path_in(file_name)
                    .to_string_lossy()
                    .into_owned(),
                // White: the file's own material colours the mesh.
                color: [1.0; 4],
                texture: None,
                shading: ShadingMode::Lit,
                // Neutral: the file's own materials give metalness, roughness and alpha.
                metallic: 0.0,
                roughness: onyx_plugin_api::Material::DEFAULT_ROUGHNESS,
                emissive: [0.0; 3],
                alpha_mode: onyx_plugin_api::AlphaMode::Opaque,
                alpha_cutoff: onyx_plugin_api::Material::DEFAULT_ALPHA_CUTOFF,
                double_sided: false,
                visible: true,
            });
        }
        if let Some(camera) = node.camera() {
            entity.camera = Some(convert_camera(&camera, first_camera));
            first_camera = false;
        }
        if let Some(light) = node.light() {
            entity.light = Some(convert_light(&light));
        }
        entities.push(entity);
    }
    entities
}

/// Whether a mesh has a primitive drawn as triangles (points and lines are not drawn yet).
pub fn has_triangles(mesh: &gltf::Mesh<'_>) -> bool {
    use gltf::mesh::Mode;
    mesh.primitives().any(|p| {
        matches!(
            p.mode(),
            Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
        )
    })
}

/// A node's local transform: its translation, rotation and scale, or its matrix decomposed
/// (a shearing matrix loses its shear; a non-finite one is the identity).
pub fn node_transform(node: &gltf::Node<'_>) -> Transform {
    let (translation, rotation, scale) = match node.transform() {
        gltf::scene::Transform::Matrix { matrix } => {
            let (s, r, t) = Mat4::from_cols_array_2d(&matrix).to_scale_rotation_translation();
            (t, r, s)
        }
        gltf::scene::Transform::Decomposed {
            translation,
            rotation,
            scale,
        } => (
            Vec3::from(translation),
            Quat::from_array(rotation),
            Vec3::from(scale),
        ),
    };
    let rotation = if rotation.length_squared() > 1e-12 {
        rotation.normalize()
    } else {
        Quat::IDENTITY
    };
    let transform = Transform {
        translation,
        rotation,
        scale,
    };
    if transform.is_finite() {
        transform
    } else {
        Transform::IDENTITY
    }
}

/// A glTF camera (looking down -Z, Y up, as Onyx's): the first one the host may draw through.
fn convert_camera(camera: &gltf::Camera<'_>, active: bool) -> Camera {
    let (projection, near, far) = match camera.projection() {
        gltf::camera::Projection::Perspective(p) => {
            let near = p.znear().max(MIN_NEAR);
            (
                Projection::Perspective { fov_y: p.yfov() },
                near,
                p.zfar().unwrap_or(near * INFINITE_FAR_OVER_NEAR),
            )
        }
        gltf::camera::Projection::Orthographic(o) => (
            Projection::Orthographic {
                height: 2.0 * o.ymag().abs(),
            },
            o.znear().max(MIN_NEAR),
            o.zfar(),
        ),
    };
    let mut converted = Camera {
        projection,
        near,
        far: if far > near { far } else { near * 2.0 },
        active,
    };
    // A value the host would refuse (NaN, a zero field of view) falls back to its default.
    if let Projection::Perspective { fov_y } = converted.projection {
        if !(fov_y.is_finite() && fov_y > 0.0) {
            converted.projection = Projection::Perspective {
                fov_y: 60f32.to_radians(),
            };
        }
    }
    if let Projection::Orthographic { height } = converted.projection {
        if !(height.is_finite() && height > 0.0) {
            converted.projection = Projection::Orthographic { height: 1.0 };
        }
    }
    converted
}

/// A `KHR_lights_punctual` light: directional (lux taken as Onyx's multiplier, casting
/// shadows as every sun does by default), point and spot ([`ONYX_PER_CANDELA`]; the spot's
/// cone kept inside what `Light::Spot` accepts); a light without a range reaches where it
/// falls to [`FADED_LUX`].
fn convert_light(light: &gltf::khr_lights_punctual::Light<'_>) -> Light {
    use gltf::khr_lights_punctual::Kind;
    let color = light.color();
    let intensity = light.intensity();
    let range = light.range().filter(|r| *r > 0.0).unwrap_or_else(|| {
        if intensity > 0.0 {
            (intensity / FADED_LUX).sqrt()
        } else {
            FALLBACK_RANGE
        }
    });
    match light.kind() {
        Kind::Directional => Light::Directional {
            color,
            intensity,
            shadows: true,
        },
        Kind::Point => Light::Point {
            color,
            intensity: intensity * ONYX_PER_CANDELA,
            range,
            shadows: false,
        },
        Kind::Spot {
            inner_cone_angle,
            outer_cone_angle,
        } => {
            let outer = if outer_cone_angle.is_finite() {
                outer_cone_angle.clamp(1e-3, std::f32::consts::FRAC_PI_2 - 1e-3)
            } else {
                std::f32::consts::FRAC_PI_4
            };
            let inner = if inner_cone_angle.is_finite() {
                inner_cone_angle.clamp(0.0, outer * 0.999)
            } else {
                0.0
            };
            Light::Spot {
                color,
                intensity: intensity * ONYX_PER_CANDELA,
                range,
                inner_angle: inner,
                outer_angle: outer,
                shadows: false,
            }
        }
    }
}
