//! `generational_handle!`: the one definition behind [`BodyHandle`](crate::BodyHandle),
//! [`ColliderHandle`](crate::ColliderHandle) and [`JointHandle`](crate::JointHandle), the
//! handles into the world's [`HandleSet`](crate::handle_set::HandleSet)s.

/// What a [`HandleSet`](crate::handle_set::HandleSet) needs of its handle type: packing and
/// unpacking a slot index and generation (each `generational_handle!` type implements it).
pub trait GenerationalHandle: Copy {
    /// Packs an index and a generation.
    fn from_parts(index: u32, generation: u32) -> Self;
    /// Slot index.
    fn index(self) -> u32;
    /// Generation of the slot when the handle was made.
    fn generation(self) -> u32;
}

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

        impl $crate::generational_handle::GenerationalHandle for $name {
            #[inline]
            fn from_parts(index: u32, generation: u32) -> Self {
                Self::from_parts(index, generation)
            }
            #[inline]
            fn index(self) -> u32 {
                self.index()
            }
            #[inline]
            fn generation(self) -> u32 {
                self.generation()
            }
        }
    };
}

pub(crate) use generational_handle;
