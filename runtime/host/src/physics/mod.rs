//! Physics: onyx-physics stepped inside the fixed step, driven by components.
//!
//! - `physics_system.rs`: [`PhysicsSystem`], components → bodies → step → components.

mod physics_system;

pub use physics_system::PhysicsSystem;
