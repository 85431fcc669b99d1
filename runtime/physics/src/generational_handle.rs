//! `generational_handle!`: the one definition behind [`BodyHandle`](crate::BodyHandle),
//! [`ColliderHandle`](crate::ColliderHandle) and [`JointHandle`](crate::JointHandle), the
//! handles into the world's [`Arena`](crate::arena)-backed sets.

/// Defines a generational handle: a `u64` with the slot index in the low 32 bits and the
/// slot's generation in the high 32, so a handle whose item was removed never resolves again,
/// even after its slot is reused. Give the type's own doc comment before its name.
macro_rules! generational_handle {
    ($(#[$doc:meta])* $name:ident) => {
        $(#[$doc])*
        #[repr(transparent)]
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub struct $name(pub u64);

        impl $name {
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
    };
}

pub(crate) use generational_handle;
