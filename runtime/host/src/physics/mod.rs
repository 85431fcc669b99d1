//! Physics: onyx-physics stepped inside the fixed step, driven by components.
//!
//! - `physics_system.rs`: [`PhysicsSystem`], components → bodies → step → components;
//!   `physics_reset.rs`: [`PhysicsSystem::reset`] when the world is replaced;
//!   `entity_map.rs`: [`EntityMap`], per-entity data without hashing.

mod entity_map;
mod physics_reset;
mod physics_system;

pub use entity_map::EntityMap;
pub use physics_system::PhysicsSystem;
