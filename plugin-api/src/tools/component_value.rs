//! [`ComponentValue`]: one component of an entity, typed — what tools read, edit, undo and
//! redo with [`Ctx::components_of`](crate::Ctx::components_of) and
//! [`Ctx::set_component`](crate::Ctx::set_component).

use crate::{BuiltinId, BuiltinValue};

/// A plugin component's value as tools see it.
#[derive(Clone, Debug, PartialEq)]
pub enum PluginValue {
    /// Stored by serde ([`Component`](crate::Component)): its value.
    Json(serde_json::Value),
    /// Stored as raw bytes ([`Ctx::set_raw`](crate::Ctx::set_raw)).
    Raw(Vec<u8>),
}

/// One component of an entity: a built-in, typed, or a plugin component by name.
#[derive(Clone, Debug, PartialEq)]
pub enum ComponentValue {
    /// A built-in component.
    Builtin(BuiltinValue),
    /// A plugin component.
    Plugin {
        /// Its name ([`Component::NAME`](crate::Component::NAME)).
        name: String,
        /// Its value.
        value: PluginValue,
    },
}

/// Which component: a built-in, or a plugin component by name.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum ComponentKey {
    /// A built-in component.
    Builtin(BuiltinId),
    /// A plugin component.
    Plugin(String),
}

impl ComponentKey {
    /// The name tools show (`Transform`, `spinner.spin`).
    pub fn name(&self) -> &str {
        match self {
            ComponentKey::Builtin(id) => id.name(),
            ComponentKey::Plugin(name) => name,
        }
    }
}

impl ComponentValue {
    /// Which component it is.
    pub fn key(&self) -> ComponentKey {
        match self {
            ComponentValue::Builtin(value) => ComponentKey::Builtin(value.id()),
            ComponentValue::Plugin { name, .. } => ComponentKey::Plugin(name.clone()),
        }
    }

    /// The name tools show.
    pub fn name(&self) -> &str {
        match self {
            ComponentValue::Builtin(value) => value.name(),
            ComponentValue::Plugin { name, .. } => name,
        }
    }
}

impl From<BuiltinValue> for ComponentValue {
    fn from(value: BuiltinValue) -> Self {
        ComponentValue::Builtin(value)
    }
}
