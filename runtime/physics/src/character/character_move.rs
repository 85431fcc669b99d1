//! [`CharacterMove`]: what one move of a character did.

use glam::Vec3;

use crate::query::ShapeHit;

/// The result of [`crate::PhysicsWorld::move_character`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CharacterMove {
    /// How far the character may move (world axes, metres): add it to its position.
    pub translation: Vec3,
    /// It ends the move standing on a walkable surface (within twice the offset).
    pub grounded: bool,
    /// The surfaces it ran into, in order (the distance of each is along that part of the
    /// move).
    pub collisions: Vec<ShapeHit>,
}
