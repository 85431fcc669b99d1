//! [`HandleSet`]: flat generational storage addressed by a typed handle — the one type behind
//! [`BodySet`](crate::BodySet), [`ColliderSet`](crate::ColliderSet) and the joints of
//! [`JointSet`](crate::JointSet).

use std::marker::PhantomData;

use crate::arena::Arena;
use crate::generational_handle::GenerationalHandle;

/// Items of one kind (bodies, colliders, joints), addressed by handle `H`.
#[derive(Clone, Debug)]
pub struct HandleSet<H, T> {
    pub(crate) arena: Arena<T>,
    handle: PhantomData<H>,
}

impl<H, T> Default for HandleSet<H, T> {
    fn default() -> Self {
        Self {
            arena: Arena::default(),
            handle: PhantomData,
        }
    }
}

impl<H: GenerationalHandle, T> HandleSet<H, T> {
    /// The item behind a handle, if still alive.
    #[must_use]
    pub fn get(&self, h: H) -> Option<&T> {
        self.arena.get(h.index(), h.generation())
    }

    /// The item behind a handle, mutably, if still alive.
    pub fn get_mut(&mut self, h: H) -> Option<&mut T> {
        self.arena.get_mut(h.index(), h.generation())
    }

    /// Number of items.
    #[must_use]
    pub fn len(&self) -> usize {
        self.arena.len()
    }

    /// True when there are none.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.arena.len() == 0
    }

    /// Iterates `(handle, item)`.
    pub fn iter(&self) -> impl Iterator<Item = (H, &T)> {
        self.arena
            .iter()
            .map(|(i, g, item)| (H::from_parts(i, g), item))
    }

    /// Iterates `(handle, item)` mutably.
    pub fn iter_mut(&mut self) -> impl Iterator<Item = (H, &mut T)> {
        self.arena
            .iter_mut()
            .map(|(i, g, item)| (H::from_parts(i, g), item))
    }

    /// The handle of the live item in slot `index`.
    pub(crate) fn handle_of(&self, index: u32) -> H {
        H::from_parts(index, self.arena.generation_of(index))
    }
}
