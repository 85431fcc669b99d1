//! [`ComponentType`]: anything [`Ctx::get`](crate::Ctx::get) and friends accept — the
//! built-in components and every [`Component`].

use abi_stable::std_types::{RString, RVec};

use crate::__ffi::{BlobFfi, BuiltinFfi, BuiltinId};
use crate::{
    BlobFormat, Camera, Collider, Component, Ctx, CtxError, Entity, Light, MeshRenderer, Name,
    RigidBody, Transform,
};

/// A component type: built-in ([`Name`], [`Transform`], …) or plugin-defined ([`Component`]).
/// Implemented by the SDK; you do not implement it yourself.
pub trait ComponentType: Sized + 'static {
    #[doc(hidden)]
    fn get_from(ctx: &mut Ctx<'_>, entity: Entity) -> Result<Self, CtxError>;
    #[doc(hidden)]
    fn set_into(self, ctx: &mut Ctx<'_>, entity: Entity) -> Result<(), CtxError>;
    #[doc(hidden)]
    fn remove_from(ctx: &mut Ctx<'_>, entity: Entity) -> Result<(), CtxError>;
    #[doc(hidden)]
    fn write_to(self, parts: &mut BundleParts) -> Result<(), CtxError>;
}

/// Components gathered for one spawn.
#[doc(hidden)]
#[derive(Default)]
pub struct BundleParts {
    pub builtins: RVec<BuiltinFfi>,
    pub blobs: RVec<BlobFfi>,
}

/// Ties a built-in component type to its id and its boundary value.
pub(crate) trait Builtin: Sized {
    const ID: BuiltinId;
    fn into_ffi(self) -> BuiltinFfi;
    fn from_ffi(value: BuiltinFfi) -> Option<Self>;
}

macro_rules! builtin {
    ($ty:ident, $wrap:expr, $unwrap:pat => $value:expr) => {
        impl Builtin for $ty {
            const ID: BuiltinId = BuiltinId::$ty;
            fn into_ffi(self) -> BuiltinFfi {
                #[allow(clippy::redundant_closure_call)]
                ($wrap)(self)
            }
            fn from_ffi(value: BuiltinFfi) -> Option<Self> {
                match value {
                    $unwrap => Some($value),
                    #[allow(unreachable_patterns)]
                    _ => None,
                }
            }
        }

        impl ComponentType for $ty {
            fn get_from(ctx: &mut Ctx<'_>, entity: Entity) -> Result<Self, CtxError> {
                let value = ctx.raw_get_builtin(entity, Self::ID)?;
                Self::from_ffi(value).ok_or_else(|| CtxError::Invalid {
                    message: format!(
                        "the host answered a `{}` request with another component",
                        Self::ID.name()
                    ),
                })
            }
            fn set_into(self, ctx: &mut Ctx<'_>, entity: Entity) -> Result<(), CtxError> {
                ctx.raw_set_builtin(entity, self.into_ffi())
            }
            fn remove_from(ctx: &mut Ctx<'_>, entity: Entity) -> Result<(), CtxError> {
                ctx.raw_remove_builtin(entity, Self::ID)
            }
            fn write_to(self, parts: &mut BundleParts) -> Result<(), CtxError> {
                parts.builtins.push(self.into_ffi());
                Ok(())
            }
        }
    };
}

builtin!(Name, |n: Name| BuiltinFfi::Name(RString::from(n.0)), BuiltinFfi::Name(n) => Name(n.into_string()));
builtin!(MeshRenderer, BuiltinFfi::MeshRenderer, BuiltinFfi::MeshRenderer(v) => v);
builtin!(Camera, BuiltinFfi::Camera, BuiltinFfi::Camera(v) => v);
builtin!(Light, BuiltinFfi::Light, BuiltinFfi::Light(v) => v);
builtin!(RigidBody, BuiltinFfi::RigidBody, BuiltinFfi::RigidBody(v) => v);
builtin!(Collider, BuiltinFfi::Collider, BuiltinFfi::Collider(v) => v);
builtin!(Transform, |t: Transform| BuiltinFfi::Transform(t.into()), BuiltinFfi::Transform(t) => t.into());

pub(crate) fn encode<T: Component>(value: &T) -> Result<RVec<u8>, CtxError> {
    serde_json::to_vec(value)
        .map(RVec::from)
        .map_err(|e| CtxError::Encode {
            component: T::NAME.to_owned(),
            message: e.to_string(),
        })
}

pub(crate) fn decode<T: Component>(format: BlobFormat, bytes: &[u8]) -> Result<T, CtxError> {
    if format != BlobFormat::Json {
        return Err(CtxError::Decode {
            component: T::NAME.to_owned(),
            message: "it is stored as raw bytes, not as a serde component".to_owned(),
        });
    }
    serde_json::from_slice(bytes).map_err(|e| CtxError::Decode {
        component: T::NAME.to_owned(),
        message: e.to_string(),
    })
}

impl<T: Component> ComponentType for T {
    fn get_from(ctx: &mut Ctx<'_>, entity: Entity) -> Result<Self, CtxError> {
        let blob = ctx.raw_get_blob(entity, T::NAME)?;
        decode(blob.format, &blob.bytes)
    }
    fn set_into(self, ctx: &mut Ctx<'_>, entity: Entity) -> Result<(), CtxError> {
        let bytes = encode(&self)?;
        ctx.raw_set_blob(entity, T::NAME, BlobFormat::Json, bytes)
    }
    fn remove_from(ctx: &mut Ctx<'_>, entity: Entity) -> Result<(), CtxError> {
        ctx.raw_remove_blob(entity, T::NAME)
    }
    fn write_to(self, parts: &mut BundleParts) -> Result<(), CtxError> {
        parts.blobs.push(BlobFfi {
            name: T::NAME.into(),
            format: BlobFormat::Json,
            bytes: encode(&self)?,
        });
        Ok(())
    }
}
