//! [`JointHandle`]: generational handle into the world's joint set.

/// Generational handle of a joint: slot index (low 32 bits) and generation (high 32 bits).
///
/// A handle whose joint was removed (or whose body was) never resolves again, even after its
/// slot is reused.
#[repr(transparent)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct JointHandle(pub u64);

impl JointHandle {
    /// A handle that never resolves.
    pub const INVALID: Self = Self(u64::MAX);

    /// Packs an index and a generation.
    #[inline]
    #[must_use]
    pub const fn from_parts(index: u32, generation: u32) -> Self {
        Self((generation as u64) << 32 | index as u64)
    }

    /// Slot index.
    #[inline]
    #[must_use]
    pub const fn index(self) -> u32 {
        self.0 as u32
    }

    /// Generation of the slot when the handle was made.
    #[inline]
    #[must_use]
    pub const fn generation(self) -> u32 {
        (self.0 >> 32) as u32
    }
}
