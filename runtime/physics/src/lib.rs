//! # onyx-physics
//!
//! Rigid-body physics for the Onyx engine: bodies, colliders, a dynamic-tree broadphase,
//! analytic + GJK/EPA narrowphase with persistent manifolds, a soft-step impulse solver
//! with substeps, sleeping, CCD, scene queries, contact events and debug lines.
//! Depends on `glam` only and knows nothing of rendering or plugins.
//!
//! ```
//! use onyx_physics::{glam::Vec3, ColliderDesc, PhysicsWorld, RigidBodyDesc};
//!
//! let mut world = PhysicsWorld::default();
//! let ground = world.insert_body(RigidBodyDesc::fixed());
//! world.insert_collider(ColliderDesc::half_space(Vec3::Y), ground);
//! let ball = world.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(0.0, 2.0, 0.0)));
//! world.insert_collider(ColliderDesc::sphere(0.5).restitution(0.5), ball);
//! for _ in 0..120 {
//!     world.step();
//! }
//! assert!(world.body(ball).unwrap().translation().y > 0.45);
//! ```
//!
//! ## Module map
//! - [`physics_world`]: [`PhysicsWorld`], the one entry point ([`PhysicsWorld::step`]) plus
//!   insertion/removal; queries in [`query`], debug lines in [`debug_lines`].
//! - Bodies: [`rigid_body`], [`rigid_body_desc`], [`body_set`], [`body_handle`], [`body_type`],
//!   [`locked_axes`], [`mass_properties`].
//! - Colliders: [`collider`], [`collider_desc`], [`collider_set`], [`collider_handle`],
//!   [`material`], [`combine_rule`], shapes in [`shape`].
//! - Pipeline: [`broadphase`] (dynamic AABB tree), [`narrowphase`] (contact generation,
//!   GJK/EPA, manifolds), [`solver`] (soft-step contact solver), private stages in `pipeline`.
//! - Characters: [`character`] ([`PhysicsWorld::move_character`], move-and-slide).
//! - Output: [`step_output`], [`step_counters`], [`contact_event`]; settings in
//!   [`physics_settings`].
//!
//! ## Conventions
//! Y up, right-handed; SI units: metres, seconds, radians, kilograms (densities kg/m³,
//! forces N, impulses N·s). All math is `f32` with `glam` types. Contact data is kept in
//! body-local coordinates and pair computations run relative to one body, so precision
//! does not depend on the distance from the origin (beyond `f32` position resolution).
//! Contact normals point from collider A to collider B.

#![warn(missing_docs)]

pub use glam;

pub mod aabb; // Axis-aligned bounding box.
pub(crate) mod arena; // Generational slot storage behind the body and collider sets.
pub mod body_handle; // `BodyHandle`: generational body handle.
pub mod body_set; // `BodySet`: flat storage of bodies.
pub mod body_type; // `BodyType`: dynamic, kinematic, static.
pub mod broadphase; // Dynamic AABB tree and new-pair search.
pub mod broken_joint; // `BrokenJoint`: a joint that broke this step (reported once).
pub mod character; // Kinematic character controller: move-and-slide, steps, snap, push.
pub mod collider; // `Collider`: shape + offset + material on a body.
pub mod collider_desc; // `ColliderDesc`: collider builder.
pub mod collider_handle; // `ColliderHandle`: generational collider handle.
pub mod collider_set; // `ColliderSet`: flat storage of colliders.
pub mod collision_groups; // `CollisionGroups`: 32 membership/filter groups per collider.
pub mod combine_rule; // `CombineRule`: how two materials mix.
pub mod contact_event; // `ContactEvent`: contact started / ended.
pub mod debug_line; // `DebugLine`: coloured segment for debug draw.
pub mod debug_lines; // `PhysicsWorld::debug_lines`: outlines, contacts, normals.
pub mod far_body; // `FarBody`: a moving body past the precise range of f32 (reported once).
pub mod generational_handle; // `generational_handle!`: the body, collider and joint handles' one definition.
pub mod handle_set; // `HandleSet`: the storage behind the body, collider and joint sets.
pub mod joint; // `Joint`: a joint in the world (description, bodies, reaction, broken).
pub mod joint_desc; // `JointDesc`: joint kinds (fixed, revolute, prismatic, spherical, distance), limits, motors, springs.
pub mod joint_error; // `JointError`: why a joint was refused.
pub mod joint_handle; // `JointHandle`: generational joint handle.
pub mod joint_set; // `JointSet`: flat storage of joints.
pub mod locked_axes; // `LockedAxes`: per-axis locks.
pub mod mass_properties; // `MassProperties`: mass, centre of mass, inertia tensor.
pub mod material; // `Material`: restitution and friction.
pub mod narrowphase; // Contact generation, GJK/EPA, persistent manifolds and pairs.
pub mod overloaded_contact; // `OverloadedContact`: a contact deeper than its budget (reported once).
pub mod physics_preset; // `PhysicsPreset`: named accuracy profiles (fast / balanced / precise).
pub mod physics_settings; // `PhysicsSettings`: every tunable with unit and cost.
pub mod physics_world; // `PhysicsWorld`: owner of everything; `step()`.
pub(crate) mod pipeline; // Private step stages (broadphase → narrowphase → solve → write-back/CCD → sleep → events).
pub mod pose; // `Pose`: rotation + translation.
pub mod query; // Scene queries: ray casts, shape casts, shape and AABB overlap.
pub mod rigid_body; // `RigidBody`: state of one body.
pub mod rigid_body_desc; // `RigidBodyDesc`: body builder.
pub mod settings_error; // `SettingsError`: a settings field outside what can be simulated.
pub mod shape; // Collision shapes (sphere, box, capsule, half space, hull, triangle mesh).
pub mod solver; // Soft-step contact solver.
pub mod speed_cap_hit; // `SpeedCapHit`: a body clamped to a speed cap (reported once).
pub mod step_counters; // `StepCounters`: stage timings and work counts.
pub mod step_output; // `StepOutput`: counters, events, quarantined bodies of a step.

pub use aabb::Aabb;
pub use body_handle::BodyHandle;
pub use body_set::BodySet;
pub use body_type::BodyType;
pub use broken_joint::BrokenJoint;
pub use character::{CharacterController, CharacterMove};
pub use collider::Collider;
pub use collider_desc::ColliderDesc;
pub use collider_handle::ColliderHandle;
pub use collider_set::ColliderSet;
pub use collision_groups::CollisionGroups;
pub use combine_rule::CombineRule;
pub use contact_event::{ContactEvent, ContactEventKind};
pub use debug_line::DebugLine;
pub use far_body::FarBody;
pub use joint::Joint;
pub use joint_desc::{JointDesc, JointKind, JointLimits, JointMotor, JointSpring, MotorTarget};
pub use joint_error::JointError;
pub use joint_handle::JointHandle;
pub use joint_set::JointSet;
pub use locked_axes::LockedAxes;
pub use mass_properties::MassProperties;
pub use material::Material;
pub use overloaded_contact::OverloadedContact;
pub use physics_preset::PhysicsPreset;
pub use physics_settings::PhysicsSettings;
pub use physics_world::PhysicsWorld;
pub use pose::Pose;
pub use query::{QueryFilter, RayHit, ShapeHit};
pub use rigid_body::RigidBody;
pub use rigid_body_desc::RigidBodyDesc;
pub use settings_error::SettingsError;
pub use shape::Shape;
pub use speed_cap_hit::{SpeedCap, SpeedCapHit};
pub use step_counters::StepCounters;
pub use step_output::StepOutput;
