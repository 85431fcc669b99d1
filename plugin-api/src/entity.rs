//! [`Entity`]: a handle to one entity of the host's world.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

/// A handle to an entity in the host's world.
///
/// It carries a generation: once the entity is despawned, the handle stays invalid even if
/// its slot is reused, so a stale handle gives [`CtxError::NoSuchEntity`](crate::CtxError)
/// instead of touching another entity.
#[repr(transparent)]
#[derive(StableAbi, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Entity(u64);

impl Entity {
    /// Builds a handle from its 64-bit form (see [`Entity::to_bits`]).
    pub const fn from_bits(bits: u64) -> Self {
        Self(bits)
    }

    /// The handle as 64 bits (index and generation), stable for the life of the entity.
    pub const fn to_bits(self) -> u64 {
        self.0
    }
}

impl std::fmt::Debug for Entity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Entity({:#x})", self.0)
    }
}

impl std::fmt::Display for Entity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // hecs packs the generation in the high 32 bits and the index in the low 32 bits.
        write!(f, "{}v{}", self.0 & 0xffff_ffff, self.0 >> 32)
    }
}
