//! [`SceneFile`]: the on-disk form of a scene (RON, versioned).

use std::collections::BTreeMap;

use onyx_plugin_api::{Camera, Light, RigidBody, ShadingMode, Transform};
use serde::{Deserialize, Serialize};

use super::ScenePhysics;

/// The scene format this host writes and reads.
pub const SCENE_FORMAT_VERSION: u32 = 1;

/// A scene file: a format version and the entities.
///
/// ```ron
/// (
///     version: 1,
///     physics: Some((preset: Balanced)),
///     entities: [
///         (
///             name: Some("crate"),
///             transform: Some((translation: (0.0, 2.0, 0.0), rotation: (0.0, 0.0, 0.0, 1.0), scale: (1.0, 1.0, 1.0))),
///             components: { "spinner.spin": Json({"speed": 1.5}), "notes.raw": Raw("AAEC") },
///         ),
///     ],
/// )
/// ```
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// Format version; see [`SCENE_FORMAT_VERSION`].
    pub version: u32,
    /// How the scene is simulated (absent: the host's current settings).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub physics: Option<ScenePhysics>,
    /// The entities, in order.
    #[serde(default)]
    pub entities: Vec<SceneEntity>,
}

/// One entity and its components. Absent components are simply not there.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneEntity {
    /// The entity's name.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// Its transform.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub transform: Option<Transform>,
    /// What it looks like.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mesh_renderer: Option<SceneMeshRenderer>,
    /// A camera at the entity's transform.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub camera: Option<Camera>,
    /// A light at the entity's transform.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub light: Option<Light>,
    /// A rigid body (needs a collider to collide).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rigid_body: Option<RigidBody>,
    /// A collision shape (without a rigid body, a static one).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub collider: Option<SceneCollider>,
    /// Plugin components by name.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub components: BTreeMap<String, SceneComponent>,
}

/// A [`MeshRenderer`](onyx_plugin_api::MeshRenderer) as a scene file writes it: meshes and
/// textures by file path (ids are only valid while a host runs).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneMeshRenderer {
    /// A built-in shape (`cube`, `sphere`, `plane`, `capsule`, `cylinder`) or a model file.
    pub mesh: String,
    /// Linear RGBA colour.
    #[serde(default = "white")]
    pub color: [f32; 4],
    /// An albedo texture file.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub texture: Option<String>,
    /// How it is shaded.
    #[serde(default)]
    pub shading: ShadingMode,
    /// Whether it is drawn.
    #[serde(default = "yes")]
    pub visible: bool,
}

fn white() -> [f32; 4] {
    [1.0; 4]
}

fn yes() -> bool {
    true
}

/// A [`Collider`](onyx_plugin_api::Collider) as a scene file writes it: mesh shapes by model
/// file path.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneCollider {
    /// The shape.
    pub shape: SceneShape,
    /// Offset from the entity's origin, local frame, metres.
    #[serde(default)]
    pub offset: [f32; 3],
    /// kg/m³.
    #[serde(default = "water")]
    pub density: f32,
    /// Bounciness 0..1.
    #[serde(default)]
    pub restitution: f32,
    /// Sliding friction.
    #[serde(default = "half")]
    pub friction: f32,
    /// Friction at rest (defaults to `friction`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub static_friction: Option<f32>,
}

fn water() -> f32 {
    1000.0
}

fn half() -> f32 {
    0.5
}

/// A collision shape in a scene file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum SceneShape {
    /// Sphere of `radius` m.
    Sphere {
        /// Radius.
        radius: f32,
    },
    /// Box with half extents.
    Box {
        /// Half extents.
        half_extents: [f32; 3],
    },
    /// Capsule along Y.
    Capsule {
        /// Half length of the straight part.
        half_height: f32,
        /// Radius.
        radius: f32,
    },
    /// Half space below the local XZ plane.
    Plane,
    /// Convex hull of a model file's vertices.
    ConvexHull {
        /// Model file.
        mesh: String,
    },
    /// Triangles of a model file (static).
    TriMesh {
        /// Model file.
        mesh: String,
    },
}

/// A plugin component in a scene file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum SceneComponent {
    /// A serde component, written as its value (readable and editable by hand).
    Json(serde_json::Value),
    /// Raw bytes, base64.
    Raw(String),
}
