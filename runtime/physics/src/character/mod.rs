//! Kinematic character controller: move-and-slide against the world with a largest climbable
//! slope, step climbing, snapping to the ground and pushing dynamic bodies
//! ([`crate::PhysicsWorld::move_character`]).
//!
//! - [`character_controller`]: [`CharacterController`], the settings of one move.
//! - [`character_move`]: [`CharacterMove`], what a move did.
//! - `move_and_slide.rs`: the move itself (slide, step, snap), read-only over the world.
//! - `push.rs`: the impulses a move gives the dynamic bodies it ran into.

pub mod character_controller;
pub mod character_move;
mod move_and_slide;
mod push;

pub use character_controller::{CharacterController, CHARACTER_MAX_SLIDES};
pub use character_move::CharacterMove;
