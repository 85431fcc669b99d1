//! [`BodySet`]: flat generational storage of rigid bodies.

use crate::arena::Arena;
use crate::body_handle::BodyHandle;
use crate::rigid_body::RigidBody;

/// All bodies of a world, addressed by [`BodyHandle`].
#[derive(Clone, Debug, Default)]
pub struct BodySet {
    pub(crate) arena: Arena<RigidBody>,
}

impl BodySet {
    /// Body behind a handle, if still alive.
    #[must_use]
    pub fn get(&self, h: BodyHandle) -> Option<&RigidBody> {
        self.arena.get(h.index(), h.generation())
    }

    /// Mutable body behind a handle, if still alive.
    pub fn get_mut(&mut self, h: BodyHandle) -> Option<&mut RigidBody> {
        self.arena.get_mut(h.index(), h.generation())
    }

    /// Number of bodies.
    #[must_use]
    pub fn len(&self) -> usize {
        self.arena.len()
    }

    /// True when there are no bodies.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.arena.len() == 0
    }

    /// Iterates `(handle, body)`.
    pub fn iter(&self) -> impl Iterator<Item = (BodyHandle, &RigidBody)> {
        self.arena
            .iter()
            .map(|(i, g, b)| (BodyHandle::from_parts(i, g), b))
    }

    /// Iterates `(handle, body)` mutably.
    pub fn iter_mut(&mut self) -> impl Iterator<Item = (BodyHandle, &mut RigidBody)> {
        self.arena
            .iter_mut()
            .map(|(i, g, b)| (BodyHandle::from_parts(i, g), b))
    }

    pub(crate) fn handle_of(&self, index: u32) -> BodyHandle {
        BodyHandle::from_parts(index, self.arena.generation_of(index))
    }
}
