//! [`Parent`]: puts an entity under another in the scene graph.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

use super::builtin::{FileRefs, HostRefs};
use crate::{Builtin, Entity, InvalidValue};

/// The entity this one hangs under: its [`Transform`](crate::Transform) is then relative to
/// the parent's world pose, and it moves with the parent.
///
/// ```no_run
/// # use onyx_plugin_api::*;
/// # fn demo(ctx: &mut Ctx) -> Result<(), CtxError> {
/// let cart = ctx.spawn((Name::new("cart"), Transform::from_xyz(0.0, 0.5, 0.0)))?;
/// // One metre above the cart, wherever the cart goes.
/// let lamp = ctx.spawn((Name::new("lamp"), Transform::from_xyz(0.0, 1.0, 0.0), Parent(cart)))?;
/// assert_eq!(ctx.children(cart)?, vec![lamp]);
/// # Ok(()) }
/// ```
///
/// Writing it (with `ctx.set`, in a spawn, or from a scene file) keeps the local transform;
/// [`Ctx::set_parent`](crate::Ctx::set_parent) can keep the world pose instead. The host
/// refuses a parent that is the entity itself, one of its descendants (a cycle) or an entity
/// that does not exist. An entity without a `Transform` passes its parent's pose on to its
/// children unchanged.
#[repr(transparent)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Parent(pub Entity);

impl Builtin for Parent {
    const NAME: &'static str = "Parent";
    /// The parent's file-local id (`id: Some(N)` on the parent's entity in the file).
    type File = u64;

    fn tool_default() -> Option<Self> {
        None
    }

    fn validate(&self, refs: &dyn HostRefs) -> Result<(), InvalidValue> {
        if refs.contains(self.0) {
            Ok(())
        } else {
            Err(InvalidValue::invalid(
                "parent",
                format!("names entity {}, which does not exist", self.0),
            ))
        }
    }

    fn to_file(&self, refs: &dyn HostRefs) -> u64 {
        refs.file_id(self.0).unwrap_or(self.0.to_bits())
    }

    fn from_file(file: u64, refs: &mut dyn FileRefs) -> Result<Self, InvalidValue> {
        refs.entity(file).map(Parent).ok_or_else(|| {
            InvalidValue::invalid("parent", format!("names id {file}, which no entity has"))
        })
    }
}

/// What [`Ctx::set_parent`](crate::Ctx::set_parent) keeps when an entity changes parent.
#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum KeepPose {
    /// The entity stays where it is in the world; its local transform is recomputed.
    #[default]
    World,
    /// The local transform stays; the entity moves with its new parent.
    Local,
}
