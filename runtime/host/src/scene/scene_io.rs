//! Reading a scene into the world, and writing the world to a scene, atomically.

use std::io::Write;
use std::path::Path;

use base64::Engine as _;
use onyx_plugin_api::{
    BlobFormat, Camera, Collider, ColliderShape, Light, Material, MeshId, MeshRenderer, Name,
    RigidBody, TextureId, Transform,
};

use super::{
    SceneCollider, SceneComponent, SceneEntity, SceneError, SceneFile, SceneMeshRenderer,
    SceneShape, SCENE_FORMAT_VERSION,
};
use crate::render::AssetRegistry;
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
    if let Some(physics) = &scene.physics {
        physics
            .validate()
            .map_err(|message| SceneError::InvalidPhysics {
                path: path.to_path_buf(),
                message,
            })?;
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
    mesh_renderer: Option<MeshRenderer>,
    camera: Option<Camera>,
    light: Option<Light>,
    rigid_body: Option<RigidBody>,
    collider: Option<Collider>,
    blobs: PluginComponents,
}

fn collider(scene: &SceneCollider, assets: &mut AssetRegistry) -> Collider {
    let shape = match &scene.shape {
        SceneShape::Sphere { radius } => ColliderShape::Sphere { radius: *radius },
        SceneShape::Box { half_extents } => ColliderShape::Box {
            half_extents: *half_extents,
        },
        SceneShape::Capsule {
            half_height,
            radius,
        } => ColliderShape::Capsule {
            half_height: *half_height,
            radius: *radius,
        },
        SceneShape::Plane => ColliderShape::Plane,
        SceneShape::ConvexHull { mesh } => ColliderShape::ConvexHull {
            mesh: assets.mesh(Path::new(mesh)),
        },
        SceneShape::TriMesh { mesh } => ColliderShape::TriMesh {
            mesh: assets.mesh(Path::new(mesh)),
        },
    };
    Collider {
        shape,
        offset: scene.offset,
        density: scene.density,
        restitution: scene.restitution,
        friction: scene.friction,
        static_friction: scene.static_friction.unwrap_or(scene.friction),
    }
}

/// A collider as a scene writes it (mesh shapes by path).
pub fn scene_collider(c: &Collider, assets: &AssetRegistry) -> SceneCollider {
    let path = |mesh| {
        assets
            .mesh_path(mesh)
            .map(|p| p.display().to_string())
            .unwrap_or_default()
    };
    let shape = match c.shape {
        ColliderShape::Sphere { radius } => SceneShape::Sphere { radius },
        ColliderShape::Box { half_extents } => SceneShape::Box { half_extents },
        ColliderShape::Capsule {
            half_height,
            radius,
        } => SceneShape::Capsule {
            half_height,
            radius,
        },
        ColliderShape::Plane => SceneShape::Plane,
        ColliderShape::ConvexHull { mesh } => SceneShape::ConvexHull { mesh: path(mesh) },
        ColliderShape::TriMesh { mesh } => SceneShape::TriMesh { mesh: path(mesh) },
    };
    SceneCollider {
        shape,
        offset: c.offset,
        density: c.density,
        restitution: c.restitution,
        friction: c.friction,
        static_friction: (c.static_friction != c.friction).then_some(c.static_friction),
    }
}

fn mesh_renderer(scene: &SceneMeshRenderer, assets: &mut AssetRegistry) -> MeshRenderer {
    let mesh = MeshId::BUILTIN
        .iter()
        .find(|(_, name)| *name == scene.mesh)
        .map(|(id, _)| *id)
        .unwrap_or_else(|| assets.mesh(Path::new(&scene.mesh)));
    let texture = scene
        .texture
        .as_deref()
        .map_or(TextureId::NONE, |t| assets.texture(Path::new(t)));
    MeshRenderer {
        mesh,
        material: Material {
            color: scene.color,
            texture,
            shading: scene.shading,
        },
        visible: scene.visible,
    }
}

fn prepare(
    entity: &SceneEntity,
    index: usize,
    path: &Path,
    assets: &mut AssetRegistry,
) -> Result<Prepared, SceneError> {
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
    if let Some(r) = &entity.mesh_renderer {
        if !r.color.iter().all(|c| c.is_finite()) {
            return Err(invalid(
                "its mesh_renderer colour holds NaN or infinity".into(),
            ));
        }
        if r.mesh.is_empty() {
            return Err(invalid("its mesh_renderer names no mesh".into()));
        }
    }
    if let Some(c) = &entity.camera {
        let extent = match c.projection {
            onyx_plugin_api::Projection::Perspective { fov_y } => fov_y,
            onyx_plugin_api::Projection::Orthographic { height } => height,
        };
        if !(c.near > 0.0
            && c.far > c.near
            && extent > 0.0
            && c.far.is_finite()
            && extent.is_finite())
        {
            return Err(invalid(
                "its camera needs 0 < near < far and a positive fov_y or height".into(),
            ));
        }
    }
    if entity.light.is_some_and(|l| !l.is_finite()) {
        return Err(invalid("its light holds NaN or infinity".into()));
    }
    if entity
        .rigid_body
        .is_some_and(|b| !b.is_finite() || b.mass < 0.0)
    {
        return Err(invalid(
            "its rigid_body holds NaN, infinity or a negative mass".into(),
        ));
    }
    let collider = entity.collider.as_ref().map(|c| collider(c, assets));
    if collider.is_some_and(|c| !c.is_valid()) {
        return Err(invalid(
            "its collider needs finite values, positive sizes and non-negative density and friction"
                .into(),
        ));
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
        mesh_renderer: entity
            .mesh_renderer
            .as_ref()
            .map(|r| mesh_renderer(r, assets)),
        camera: entity.camera,
        light: entity.light,
        rigid_body: entity.rigid_body,
        collider,
        blobs,
    })
}

/// Spawns every entity of `scene` into `world`. All entities are checked first: on error the
/// world is unchanged. Returns the number of entities spawned.
pub fn spawn_scene(
    world: &mut hecs::World,
    assets: &mut AssetRegistry,
    scene: &SceneFile,
    path: &Path,
) -> Result<usize, SceneError> {
    let prepared = scene
        .entities
        .iter()
        .enumerate()
        .map(|(i, e)| prepare(e, i, path, assets))
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
        if let Some(r) = p.mesh_renderer {
            let _ = world.insert_one(e, r);
        }
        if let Some(c) = p.camera {
            let _ = world.insert_one(e, c);
        }
        if let Some(l) = p.light {
            let _ = world.insert_one(e, l);
        }
        if let Some(b) = p.rigid_body {
            let _ = world.insert_one(e, b);
        }
        if let Some(c) = p.collider {
            let _ = world.insert_one(e, c);
        }
        if !p.blobs.0.is_empty() {
            let _ = world.insert_one(e, p.blobs);
        }
    }
    Ok(count)
}

/// A mesh renderer as a scene writes it (meshes and textures by path).
pub fn scene_mesh_renderer(r: &MeshRenderer, assets: &AssetRegistry) -> SceneMeshRenderer {
    let mesh = MeshId::BUILTIN
        .iter()
        .find(|(id, _)| *id == r.mesh)
        .map(|(_, name)| (*name).to_owned())
        .or_else(|| assets.mesh_path(r.mesh).map(|p| p.display().to_string()))
        .unwrap_or_else(|| "cube".to_owned());
    SceneMeshRenderer {
        mesh,
        color: r.material.color,
        texture: assets
            .texture_path(r.material.texture)
            .map(|p| p.display().to_string()),
        shading: r.material.shading,
        visible: r.visible,
    }
}

/// The world as a scene file, entities in id order.
pub fn scene_from_world(world: &hecs::World, assets: &AssetRegistry) -> SceneFile {
    let mut ids: Vec<hecs::Entity> = world.iter().map(|e| e.entity()).collect();
    ids.sort_by_key(|e| e.to_bits());
    let entities = ids
        .into_iter()
        .map(|e| {
            let name = world.get::<&Name>(e).ok().map(|n| n.0.clone());
            let transform = world.get::<&Transform>(e).ok().map(|t| *t);
            let mesh_renderer = world
                .get::<&MeshRenderer>(e)
                .ok()
                .map(|r| scene_mesh_renderer(&r, assets));
            let camera = world.get::<&Camera>(e).ok().map(|c| *c);
            let light = world.get::<&Light>(e).ok().map(|l| *l);
            let rigid_body = world.get::<&RigidBody>(e).ok().map(|b| *b);
            let collider = world
                .get::<&Collider>(e)
                .ok()
                .map(|c| scene_collider(&c, assets));
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
                mesh_renderer,
                camera,
                light,
                rigid_body,
                collider,
                components,
            }
        })
        .collect();
    SceneFile {
        version: SCENE_FORMAT_VERSION,
        physics: None,
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
