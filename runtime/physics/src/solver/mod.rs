//! Soft-step impulse solver: [`Softness`], solver bodies, contact constraints, substep loop.

pub(crate) mod batching;
pub(crate) mod body_state;
pub(crate) mod column_chain;
pub(crate) mod column_solve;
pub(crate) mod contact_batch;
pub(crate) mod contact_constraint;
pub mod elastic_energy;
pub(crate) mod face_contact;
pub mod free_rotation;
pub(crate) mod joint_constraint;
pub(crate) mod lanes;
pub(crate) mod noise;
pub mod restitution;
pub mod softness;
pub(crate) mod solve;
pub(crate) mod solver_body;

pub(crate) use contact_batch::LEVEL_MAX_FRICTION;
pub use softness::Softness;
