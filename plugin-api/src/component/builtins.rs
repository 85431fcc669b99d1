//! The list of built-in components, and what it makes: [`BuiltinId`], [`BuiltinValue`] and
//! the typed `Ctx` calls of each.
//!
//! Adding a built-in component is two steps: a file with the type and its
//! [`Builtin`](crate::Builtin) impl, and one line in [`for_each_builtin!`]. The boundary, the
//! host's world, scene files, state dumps, play-mode snapshots and the editor all iterate
//! this list.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

use super::builtin::{Builtin, BuiltinFn, BuiltinVisitor, HostRefs, InvalidValue, Listed};
use super::component_type::BundleParts;
use crate::{ComponentType, Ctx, CtxError, Entity};

/// Calls macro `$then` with every built-in component, in the order tools show them:
/// `Variant => scene_key: Type as BoundaryType`. The one list of built-ins.
#[doc(hidden)]
#[macro_export]
macro_rules! for_each_builtin {
    ($then:ident) => {
        $then! {
            Name => name: $crate::Name as $crate::__ffi::NameFfi,
            Transform => transform: $crate::Transform as $crate::__ffi::TransformFfi,
            Parent => parent: $crate::Parent as $crate::Parent,
            MeshRenderer => mesh_renderer: $crate::MeshRenderer as $crate::MeshRenderer,
            Camera => camera: $crate::Camera as $crate::Camera,
            Light => light: $crate::Light as $crate::Light,
            RigidBody => rigid_body: $crate::RigidBody as $crate::RigidBody,
            Collider => collider: $crate::Collider as $crate::Collider,
            Animator => animator: $crate::Animator as $crate::Animator,
            Joint => joint: $crate::Joint as $crate::Joint,
        }
    };
}

macro_rules! define_builtins {
    ($($id:ident => $key:ident: $ty:ty as $ffi:ty),* $(,)?) => {
        /// Which built-in component: the key of [`BuiltinValue`], in list order.
        #[repr(u8)]
        #[derive(
            StableAbi, Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize,
            Deserialize,
        )]
        pub enum BuiltinId {
            $(
                #[doc = concat!("[`", stringify!($id), "`](crate::", stringify!($id), ")")]
                $id,
            )*
        }

        impl BuiltinId {
            /// Every built-in, in the order tools show them.
            pub const ALL: &'static [BuiltinId] = &[$(BuiltinId::$id),*];

            /// The stable name (`"Transform"`).
            pub fn name(self) -> &'static str {
                match self {
                    $(BuiltinId::$id => <$ty as Builtin>::NAME,)*
                }
            }

            /// The key of the component in a scene-file entity (`transform`).
            pub fn scene_key(self) -> &'static str {
                match self {
                    $(BuiltinId::$id => stringify!($key),)*
                }
            }

            /// Calls `f` with the component type of this id.
            pub fn dispatch<F: BuiltinFn>(self, f: &mut F) -> F::Output {
                match self {
                    $(BuiltinId::$id => f.call::<$ty>(),)*
                }
            }
        }

        /// A value of one of the built-in components.
        #[derive(Clone, Debug, PartialEq)]
        #[non_exhaustive]
        pub enum BuiltinValue {
            $(
                #[doc = concat!("A [`", stringify!($id), "`](crate::", stringify!($id), ").")]
                $id($ty),
            )*
        }

        impl BuiltinValue {
            /// Which component this is.
            pub fn id(&self) -> BuiltinId {
                match self {
                    $(BuiltinValue::$id(_) => BuiltinId::$id,)*
                }
            }

            /// Calls `f` with the value, typed.
            pub fn visit<F: BuiltinVisitor>(&self, f: &mut F) -> F::Output {
                match self {
                    $(BuiltinValue::$id(value) => f.call(value),)*
                }
            }
        }

        $(
            impl Listed for $ty {
                const ID: BuiltinId = BuiltinId::$id;
                fn into_value(self) -> BuiltinValue {
                    BuiltinValue::$id(self)
                }
                fn from_value(value: BuiltinValue) -> Result<Self, BuiltinValue> {
                    match value {
                        BuiltinValue::$id(value) => Ok(value),
                        #[allow(unreachable_patterns)]
                        other => Err(other),
                    }
                }
                fn ref_from(value: &BuiltinValue) -> Option<&Self> {
                    match value {
                        BuiltinValue::$id(value) => Some(value),
                        #[allow(unreachable_patterns)]
                        _ => None,
                    }
                }
            }

            impl From<$ty> for BuiltinValue {
                fn from(value: $ty) -> Self {
                    BuiltinValue::$id(value)
                }
            }

            impl ComponentType for $ty {
                fn get_from(ctx: &mut Ctx<'_>, entity: Entity) -> Result<Self, CtxError> {
                    let value = ctx.get_builtin(entity, BuiltinId::$id)?;
                    <$ty as Listed>::from_value(value).map_err(|other| CtxError::Invalid {
                        message: format!(
                            "the host answered a `{}` request with a `{}`",
                            <$ty as Builtin>::NAME,
                            other.id().name()
                        ),
                    })
                }
                fn set_into(self, ctx: &mut Ctx<'_>, entity: Entity) -> Result<(), CtxError> {
                    ctx.set_builtin(entity, BuiltinValue::$id(self))
                }
                fn remove_from(ctx: &mut Ctx<'_>, entity: Entity) -> Result<(), CtxError> {
                    ctx.remove_builtin(entity, BuiltinId::$id)
                }
                fn write_to(self, parts: &mut BundleParts) -> Result<(), CtxError> {
                    parts.builtins.push(BuiltinValue::$id(self).into());
                    Ok(())
                }
            }
        )*
    };
}

for_each_builtin!(define_builtins);

impl std::fmt::Display for BuiltinId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl BuiltinId {
    /// The built-in named `name` (as [`BuiltinId::name`] gives it).
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.iter().copied().find(|id| id.name() == name)
    }

    /// The built-in written under `key` in scene files.
    pub fn from_scene_key(key: &str) -> Option<Self> {
        Self::ALL.iter().copied().find(|id| id.scene_key() == key)
    }

    /// The value a tool adds for this component, if it has a sensible default.
    pub fn tool_default(self) -> Option<BuiltinValue> {
        struct ToolDefault;
        impl BuiltinFn for ToolDefault {
            type Output = Option<BuiltinValue>;
            fn call<T: Builtin>(&mut self) -> Self::Output {
                T::tool_default().map(T::into_value)
            }
        }
        self.dispatch(&mut ToolDefault)
    }

    /// Reads this component from JSON (the form [`BuiltinValue::to_json`] writes).
    pub fn value_from_json(self, json: serde_json::Value) -> Result<BuiltinValue, String> {
        struct Parse(Option<serde_json::Value>);
        impl BuiltinFn for Parse {
            type Output = Result<BuiltinValue, String>;
            fn call<T: Builtin>(&mut self) -> Self::Output {
                let json = self.0.take().unwrap_or_default();
                serde_json::from_value::<T>(json)
                    .map(T::into_value)
                    .map_err(|e| e.to_string())
            }
        }
        self.dispatch(&mut Parse(Some(json)))
    }
}

impl BuiltinValue {
    /// The component's stable name.
    pub fn name(&self) -> &'static str {
        self.id().name()
    }

    /// The value, if it is a `T`.
    pub fn get<T: Builtin>(&self) -> Option<&T> {
        T::ref_from(self)
    }

    /// The value as a `T`, or itself back when it is another component.
    #[allow(clippy::result_large_err)] // See `Listed::from_value`.
    pub fn into_inner<T: Builtin>(self) -> Result<T, Self> {
        T::from_value(self)
    }

    /// Checks the value as the host does before writing it.
    pub fn validate(&self, refs: &dyn HostRefs) -> Result<(), InvalidValue> {
        struct Validate<'r>(&'r dyn HostRefs);
        impl BuiltinVisitor for Validate<'_> {
            type Output = Result<(), InvalidValue>;
            fn call<T: Builtin>(&mut self, value: &T) -> Self::Output {
                value.validate(self.0)
            }
        }
        self.visit(&mut Validate(refs))
    }

    /// The value as JSON, field by field (its serde form, ids as numbers): what a tool shows
    /// when it has no widget of its own for the component.
    pub fn to_json(&self) -> serde_json::Value {
        struct Json;
        impl BuiltinVisitor for Json {
            type Output = serde_json::Value;
            fn call<T: Builtin>(&mut self, value: &T) -> Self::Output {
                serde_json::to_value(value).unwrap_or_default()
            }
        }
        self.visit(&mut Json)
    }

    /// The value in its scene-file form, as JSON (what state dumps show).
    pub fn file_json(&self, refs: &dyn HostRefs) -> serde_json::Value {
        struct FileJson<'r>(&'r dyn HostRefs);
        impl BuiltinVisitor for FileJson<'_> {
            type Output = serde_json::Value;
            fn call<T: Builtin>(&mut self, value: &T) -> Self::Output {
                serde_json::to_value(value.to_file(self.0)).unwrap_or_default()
            }
        }
        self.visit(&mut FileJson(refs))
    }
}
