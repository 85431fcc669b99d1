//! [`ComponentType`]: anything [`Ctx::get`](crate::Ctx::get) and friends accept — the
//! built-in components and every [`Component`].

use abi_stable::std_types::RVec;

use crate::__ffi::{BlobFfi, BuiltinFfi};
use crate::{BlobFormat, Component, Ctx, CtxError, Entity};

/// A component type: built-in ([`Name`](crate::Name), [`Transform`](crate::Transform), …;
/// see [`Builtin`](crate::Builtin)) or plugin-defined ([`Component`]).
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
