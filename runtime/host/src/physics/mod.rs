//! Physics: onyx-physics stepped inside the fixed step, driven by components.
//!
//! - `physics_system.rs`: [`PhysicsSystem`], components → bodies → step → components;
//!   `physics_reset.rs`: [`PhysicsSystem::reset`] when the world is replaced.
//! - `scene_physics.rs`: [`ScenePhysics`], the preset and overrides a scene asks for.

mod physics_reset;
mod physics_system;
mod scene_physics;

pub use physics_system::PhysicsSystem;
pub use scene_physics::{ScenePhysics, MAX_SCENE_FIXED_HZ, MAX_SCENE_SUBSTEPS};
