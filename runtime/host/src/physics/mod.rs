//! Physics: onyx-physics stepped inside the fixed step, driven by components.
//!
//! - `physics_system.rs`: [`PhysicsSystem`], components → bodies → step → components;
//!   `physics_reset.rs`: [`PhysicsSystem::reset`] when the world is replaced.
//! - `compound.rs`: which body each collider belongs to (its entity's `RigidBody` or the
//!   nearest ancestor's) and where it sits on it, scaled with its entity.
//! - `physics_queries.rs`: overlap queries, shape casts, joint coordinates and kinematic
//!   characters, as plugins ask for them.
//! - `joint_links.rs`: `Joint` components → physics joints (made at the bodies' poses).
//! - `scene_physics.rs`: [`ScenePhysics`], the preset and every setting a scene asks for.
//! - `step_reports.rs`: the warnings a step raises (overloaded contacts, speed caps, far
//!   bodies), logged once per entity.

mod compound;
mod joint_links;
mod physics_queries;
mod physics_reset;
mod physics_system;
mod scene_physics;
mod step_reports;

pub use physics_system::PhysicsSystem;
pub use scene_physics::{
    ScenePhysics, MAX_SCENE_FIXED_HZ, MAX_SCENE_ITERATIONS, MAX_SCENE_SUBSTEPS,
    SCENE_PHYSICS_FIELDS,
};
