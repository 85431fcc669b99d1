//! [`SceneFile`]: the on-disk form of a scene (RON, versioned).

use std::collections::BTreeMap;

use onyx_plugin_api::Transform;
use serde::{Deserialize, Serialize};

/// The scene format this host writes and reads.
pub const SCENE_FORMAT_VERSION: u32 = 1;

/// A scene file: a format version and the entities.
///
/// ```ron
/// (
///     version: 1,
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
    /// Plugin components by name.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub components: BTreeMap<String, SceneComponent>,
}

/// A plugin component in a scene file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum SceneComponent {
    /// A serde component, written as its value (readable and editable by hand).
    Json(serde_json::Value),
    /// Raw bytes, base64.
    Raw(String),
}
