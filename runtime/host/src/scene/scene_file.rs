//! [`SceneFile`]: the on-disk form of a scene (RON, versioned).

use std::collections::BTreeMap;

use onyx_plugin_api::{Builtin, BuiltinId, BuiltinValue, FileRefs, HostRefs, InvalidValue, Listed};
use serde::{Deserialize, Serialize};

use crate::physics::ScenePhysics;

/// The scene format this host writes. Version 2 added entity ids and parents; in version 3
/// colliders scale with their entity (older files are brought forward as they are read).
pub const SCENE_FORMAT_VERSION: u32 = 3;
/// The oldest scene format this host still reads.
pub const OLDEST_SCENE_FORMAT_VERSION: u32 = 1;

/// A scene file: a format version, optional physics settings, and the entities.
///
/// ```ron
/// (
///     version: 3,
///     physics: Some((preset: Balanced)),
///     entities: [
///         (
///             id: Some(1),
///             name: Some("cart"),
///             transform: Some((translation: (0.0, 0.5, 0.0), rotation: (0.0, 0.0, 0.0, 1.0), scale: (1.0, 1.0, 1.0))),
///             components: { "spinner.spin": Json({"speed": 1.5}), "notes.raw": Raw("AAEC") },
///         ),
///         (
///             name: Some("lamp"),
///             parent: Some(1),
///             transform: Some((translation: (0.0, 1.0, 0.0))),
///             light: Some(Point(color: (1.0, 0.9, 0.8), intensity: 2.0, range: 6.0)),
///         ),
///     ],
/// )
/// ```
///
/// Each built-in component has its key (`name`, `transform`, `parent`, `mesh_renderer`, …:
/// see [`BuiltinId::scene_key`]); absent ones are simply not there. An entity's `parent`
/// names another entity's `id`, which is local to the file.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// Format version; see [`SCENE_FORMAT_VERSION`].
    pub version: u32,
    /// How the scene is simulated (absent: the host's current settings).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub physics: Option<ScenePhysics>,
    /// How model files are imported, by path as the entities write them (absent: as
    /// they are).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub imports: BTreeMap<String, super::ImportSettingsFile>,
    /// The entities, in order.
    #[serde(default)]
    pub entities: Vec<SceneEntity>,
}

macro_rules! scene_entity {
    ($($id:ident => $key:ident: $ty:ty as $ffi:ty),* $(,)?) => {
        /// One entity: its file-local id, each built-in component under its key in its
        /// file form, and plugin components by name.
        #[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
        #[serde(deny_unknown_fields)]
        pub struct SceneEntity {
            /// The id other entities of this file name it by in their `parent` (unique in
            /// the file).
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub id: Option<u64>,
            $(
                #[doc = concat!("Its [`", stringify!($id), "`](onyx_plugin_api::", stringify!($id), "), in file form.")]
                #[serde(default, skip_serializing_if = "Option::is_none")]
                pub $key: Option<<$ty as Builtin>::File>,
            )*
            /// Plugin components by name.
            #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
            pub components: BTreeMap<String, SceneComponent>,
        }

        impl SceneEntity {
            /// Its built-in components read from their file forms, in list order (the assets
            /// they name registered), or the first that is refused.
            pub fn builtins(
                &self,
                refs: &mut dyn FileRefs,
            ) -> Result<Vec<BuiltinValue>, (BuiltinId, InvalidValue)> {
                let mut values = Vec::new();
                $(
                    if let Some(file) = &self.$key {
                        let value = <$ty as Builtin>::from_file(file.clone(), refs)
                            .map_err(|e| (<$ty as Listed>::ID, e))?;
                        values.push(value.into());
                    }
                )*
                Ok(values)
            }

            /// Writes `value` under its key, in its file form.
            pub fn set_builtin(&mut self, value: &BuiltinValue, refs: &dyn HostRefs) {
                match value {
                    $(BuiltinValue::$id(v) => self.$key = Some(v.to_file(refs)),)*
                    _ => {}
                }
            }
        }
    };
}

onyx_plugin_api::for_each_builtin!(scene_entity);

/// A plugin component in a scene file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum SceneComponent {
    /// A serde component, written as its value (readable and editable by hand).
    Json(serde_json::Value),
    /// Raw bytes, base64.
    Raw(String),
}
