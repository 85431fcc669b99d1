//! [`BuiltinValue`]: a built-in component value, for hosts.

use crate::host::BuiltinId;
use crate::{Camera, Collider, Light, MeshRenderer, Name, RigidBody, Transform};

/// One built-in component with its value.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum BuiltinValue {
    /// A [`Name`].
    Name(Name),
    /// A [`Transform`].
    Transform(Transform),
    /// A [`MeshRenderer`].
    MeshRenderer(MeshRenderer),
    /// A [`Camera`].
    Camera(Camera),
    /// A [`Light`].
    Light(Light),
    /// A [`RigidBody`].
    RigidBody(RigidBody),
    /// A [`Collider`].
    Collider(Collider),
}

impl BuiltinValue {
    /// Which built-in component this is.
    pub fn id(&self) -> BuiltinId {
        match self {
            BuiltinValue::Name(_) => BuiltinId::Name,
            BuiltinValue::Transform(_) => BuiltinId::Transform,
            BuiltinValue::MeshRenderer(_) => BuiltinId::MeshRenderer,
            BuiltinValue::Camera(_) => BuiltinId::Camera,
            BuiltinValue::Light(_) => BuiltinId::Light,
            BuiltinValue::RigidBody(_) => BuiltinId::RigidBody,
            BuiltinValue::Collider(_) => BuiltinId::Collider,
        }
    }
}
