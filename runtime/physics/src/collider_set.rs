//! [`ColliderSet`]: flat generational storage of colliders.

use crate::arena::Arena;
use crate::collider::Collider;
use crate::collider_handle::ColliderHandle;

/// All colliders of a world, addressed by [`ColliderHandle`].
#[derive(Clone, Debug, Default)]
pub struct ColliderSet {
    pub(crate) arena: Arena<Collider>,
}

impl ColliderSet {
    /// Collider behind a handle, if still alive.
    #[must_use]
    pub fn get(&self, h: ColliderHandle) -> Option<&Collider> {
        self.arena.get(h.index(), h.generation())
    }

    /// Mutable collider behind a handle, if still alive.
    pub fn get_mut(&mut self, h: ColliderHandle) -> Option<&mut Collider> {
        self.arena.get_mut(h.index(), h.generation())
    }

    /// Number of colliders.
    #[must_use]
    pub fn len(&self) -> usize {
        self.arena.len()
    }

    /// True when there are no colliders.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.arena.len() == 0
    }

    /// Iterates `(handle, collider)`.
    pub fn iter(&self) -> impl Iterator<Item = (ColliderHandle, &Collider)> {
        self.arena
            .iter()
            .map(|(i, g, c)| (ColliderHandle::from_parts(i, g), c))
    }

    pub(crate) fn handle_of(&self, index: u32) -> ColliderHandle {
        ColliderHandle::from_parts(index, self.arena.generation_of(index))
    }
}
