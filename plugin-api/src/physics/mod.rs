//! Physics queries and the character controller, as plugins pass them to [`Ctx`](crate::Ctx).
//!
//! - `query_filter.rs`: [`QueryFilter`], which colliders an overlap or shape cast sees.
//! - `character_controller.rs`: [`CharacterController`], how
//!   [`Ctx::move_character`](crate::Ctx::move_character) moves a character, and
//!   [`CharacterMove`], what the move did.

mod character_controller;
mod query_filter;

pub use character_controller::{CharacterController, CharacterMove};
pub use query_filter::QueryFilter;
