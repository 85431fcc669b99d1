//! [`EntityTransform`]: one row of a bulk transform query.

use abi_stable::StableAbi;

use crate::{Entity, Transform};

/// An entity and its transform, as returned in bulk by
/// [`Ctx::transforms`](crate::Ctx::transforms) and written back by
/// [`Ctx::set_transforms`](crate::Ctx::set_transforms).
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct EntityTransform {
    /// The entity.
    pub entity: Entity,
    /// Its transform.
    pub transform: Transform,
}
