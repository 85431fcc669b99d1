//! Components by type name as JSON text: what the inspector lists, edits, adds and removes.

use base64::Engine as _;
use onyx_plugin_api::host::{Blob, BuiltinId, BuiltinValue, HostServices};
use onyx_plugin_api::tools::ComponentEntry;
use onyx_plugin_api::{
    BlobFormat, Camera, Collider, Component, CtxError, Entity, Light, MeshId, MeshRenderer, Name,
    RigidBody, Script, Transform,
};
use serde::de::DeserializeOwned;

use super::{CallContext, PluginComponents};

/// The built-in components, in the order an inspector shows them.
pub(super) const BUILTINS: [BuiltinId; 7] = [
    BuiltinId::Name,
    BuiltinId::Transform,
    BuiltinId::MeshRenderer,
    BuiltinId::Camera,
    BuiltinId::Light,
    BuiltinId::RigidBody,
    BuiltinId::Collider,
];

fn builtin_id(type_name: &str) -> Option<BuiltinId> {
    BUILTINS.into_iter().find(|id| id.name() == type_name)
}

fn encode(type_name: &str, value: &impl serde::Serialize) -> Result<String, CtxError> {
    serde_json::to_string(value).map_err(|e| CtxError::Encode {
        component: type_name.to_owned(),
        message: e.to_string(),
    })
}

fn parse<T: DeserializeOwned>(type_name: &str, json: &str) -> Result<T, CtxError> {
    serde_json::from_str(json).map_err(|e| CtxError::Decode {
        component: type_name.to_owned(),
        message: e.to_string(),
    })
}

fn builtin_json(value: &BuiltinValue) -> Result<String, CtxError> {
    let name = value.id().name();
    match value {
        BuiltinValue::Name(v) => encode(name, v),
        BuiltinValue::Transform(v) => encode(name, v),
        BuiltinValue::MeshRenderer(v) => encode(name, v),
        BuiltinValue::Camera(v) => encode(name, v),
        BuiltinValue::Light(v) => encode(name, v),
        BuiltinValue::RigidBody(v) => encode(name, v),
        BuiltinValue::Collider(v) => encode(name, v),
        _ => Err(CtxError::Invalid {
            message: format!("`{name}` cannot be shown as JSON"),
        }),
    }
}

fn parse_builtin(id: BuiltinId, json: &str) -> Result<BuiltinValue, CtxError> {
    let name = id.name();
    Ok(match id {
        BuiltinId::Name => BuiltinValue::Name(parse::<Name>(name, json)?),
        BuiltinId::Transform => BuiltinValue::Transform(parse::<Transform>(name, json)?),
        BuiltinId::MeshRenderer => BuiltinValue::MeshRenderer(parse::<MeshRenderer>(name, json)?),
        BuiltinId::Camera => BuiltinValue::Camera(parse::<Camera>(name, json)?),
        BuiltinId::Light => BuiltinValue::Light(parse::<Light>(name, json)?),
        BuiltinId::RigidBody => BuiltinValue::RigidBody(parse::<RigidBody>(name, json)?),
        BuiltinId::Collider => BuiltinValue::Collider(parse::<Collider>(name, json)?),
    })
}

fn default_builtin(id: BuiltinId) -> BuiltinValue {
    match id {
        BuiltinId::Name => BuiltinValue::Name(Name::new("entity")),
        BuiltinId::Transform => BuiltinValue::Transform(Transform::IDENTITY),
        BuiltinId::MeshRenderer => BuiltinValue::MeshRenderer(MeshRenderer::new(MeshId::CUBE)),
        BuiltinId::Camera => BuiltinValue::Camera(Camera::perspective(60f32.to_radians())),
        BuiltinId::Light => BuiltinValue::Light(Light::sun()),
        BuiltinId::RigidBody => BuiltinValue::RigidBody(RigidBody::default()),
        BuiltinId::Collider => BuiltinValue::Collider(Collider::cuboid(0.5, 0.5, 0.5)),
    }
}

impl CallContext<'_> {
    /// Every component of `entity` as JSON text: built-ins first, then plugin components
    /// by name.
    pub(super) fn list_components(
        &mut self,
        entity: Entity,
    ) -> Result<Vec<ComponentEntry>, CtxError> {
        let e = self.entity(entity)?;
        let mut entries = Vec::new();
        for id in BUILTINS {
            if let Ok(value) = self.get_builtin(entity, id) {
                entries.push(ComponentEntry {
                    type_name: id.name().to_owned(),
                    builtin: true,
                    value: builtin_json(&value)?,
                });
            }
        }
        if let Ok(map) = self.state.world.get::<&PluginComponents>(e) {
            for (name, stored) in &map.0 {
                let value = match stored.format {
                    BlobFormat::Json => String::from_utf8_lossy(&stored.bytes).into_owned(),
                    BlobFormat::Raw => encode(
                        name,
                        &base64::engine::general_purpose::STANDARD.encode(&stored.bytes),
                    )?,
                };
                entries.push(ComponentEntry {
                    type_name: name.clone(),
                    builtin: false,
                    value,
                });
            }
        }
        Ok(entries)
    }

    /// Writes component `type_name` from JSON, validated like every write.
    pub(super) fn write_component_json(
        &mut self,
        entity: Entity,
        type_name: &str,
        json: &str,
    ) -> Result<(), CtxError> {
        self.entity(entity)?;
        if let Some(id) = builtin_id(type_name) {
            let value = parse_builtin(id, json)?;
            return self.set_builtin(entity, value);
        }
        if type_name == Script::NAME {
            parse::<Script>(type_name, json)?;
        }
        let raw = self
            .get_blob(entity, type_name)
            .is_ok_and(|blob| blob.format == BlobFormat::Raw);
        let (format, bytes) = if raw {
            let text: String = parse(type_name, json)?;
            let bytes = base64::engine::general_purpose::STANDARD
                .decode(text)
                .map_err(|e| CtxError::Decode {
                    component: type_name.to_owned(),
                    message: format!("a raw component is written as base64: {e}"),
                })?;
            (BlobFormat::Raw, bytes)
        } else {
            let value: serde_json::Value = parse(type_name, json)?;
            (BlobFormat::Json, encode(type_name, &value)?.into_bytes())
        };
        self.set_blob(
            entity,
            Blob {
                name: type_name.to_owned(),
                format,
                bytes,
            },
        )
    }

    /// Adds built-in `type_name` (or a [`Script`]) with its default value.
    pub(super) fn add_default_component(
        &mut self,
        entity: Entity,
        type_name: &str,
    ) -> Result<(), CtxError> {
        self.entity(entity)?;
        let already = || CtxError::Invalid {
            message: format!("entity {entity} already has a `{type_name}` component"),
        };
        if let Some(id) = builtin_id(type_name) {
            if self.get_builtin(entity, id).is_ok() {
                return Err(already());
            }
            return self.set_builtin(entity, default_builtin(id));
        }
        if type_name == Script::NAME {
            if self.get_blob(entity, type_name).is_ok() {
                return Err(already());
            }
            let script = self
                .state
                .tools
                .scripts
                .all()
                .first()
                .map(|s| Script {
                    name: s.name.clone(),
                    params: s.default_params.clone(),
                })
                .unwrap_or_default();
            return self.write_component_json(entity, type_name, &encode(type_name, &script)?);
        }
        Err(CtxError::Invalid {
            message: format!(
                "`{type_name}` is not a built-in component; a plugin component has no default \
                 the host knows — set it with a value"
            ),
        })
    }

    /// Removes component `type_name`, built-in or plugin.
    pub(super) fn remove_component_named(
        &mut self,
        entity: Entity,
        type_name: &str,
    ) -> Result<(), CtxError> {
        match builtin_id(type_name) {
            Some(id) => self.remove_builtin(entity, id),
            None => self.remove_blob(entity, type_name),
        }
    }
}
