//! Components: plain data attached to entities.
//!
//! - `builtin.rs`: [`Builtin`], what each built-in component defines once (name, default,
//!   checks, scene-file form); `builtins.rs`: the list of them, [`BuiltinId`] and
//!   [`BuiltinValue`].
//! - `name.rs`, `transform.rs`, `parent.rs` ([`Parent`], [`KeepPose`]): every entity's
//!   label, local pose and place in the scene graph; `global_transform.rs`: the world pose
//!   the host computes from them.
//! - `mesh_renderer.rs` ([`MeshRenderer`], [`Material`]), `mesh_id.rs` ([`MeshId`],
//!   [`TextureId`]), `shading_mode.rs`, `alpha_mode.rs`, `camera.rs`, `light.rs`: what the
//!   renderer draws.
//! - `debug_line.rs`: [`DebugLine`], one frame's debug drawing.
//! - `rigid_body.rs` ([`RigidBody`], [`BodyKind`], [`LockedAxes`]), `collider.rs`
//!   ([`Collider`], [`ColliderShape`]), `joint.rs` ([`Joint`], [`JointTarget`]), `ray_hit.rs`
//!   ([`RayHit`]): physics.
//! - `animator.rs`: [`Animator`] ([`AnimationId`]), a node animation playing on the
//!   entities below.
//! - `component.rs`: [`Component`], a plugin's own serde component.
//! - `component_type.rs`: [`ComponentType`], what `Ctx::get`/`set`/`remove` accept.
//! - `bundle.rs`: [`Bundle`], components spawned together.
//! - `entity_transform.rs`, `blob_format.rs`: rows of bulk queries, raw-blob encodings.

mod alpha_mode;
mod animator;
mod blob_format;
mod builtin;
mod builtins;
mod bundle;
mod camera;
mod collider;
#[allow(clippy::module_inception)]
mod component;
pub(crate) mod component_type;
mod debug_line;
mod entity_transform;
mod global_transform;
mod joint;
mod light;
mod mesh_id;
mod mesh_renderer;
mod name;
mod parent;
mod ray_hit;
mod rigid_body;
mod shading_mode;
mod transform;

pub use alpha_mode::AlphaMode;
pub use animator::{AnimationId, Animator, AnimatorFile};
pub use blob_format::BlobFormat;
pub use builtin::{Builtin, BuiltinFn, BuiltinVisitor, FileRefs, HostRefs, InvalidValue, Listed};
pub use builtins::{BuiltinId, BuiltinValue};
pub use bundle::Bundle;
pub use camera::{Camera, Projection};
pub use collider::{Collider, ColliderFile, ColliderShape, ColliderShapeFile};
pub use component::Component;
pub use component_type::ComponentType;
pub use debug_line::DebugLine;
pub use entity_transform::EntityTransform;
pub use global_transform::GlobalTransform;
pub use joint::{Joint, JointFile, JointKind, JointMotor, JointTarget};
pub use light::Light;
pub use mesh_id::{MeshId, TextureId};
pub use mesh_renderer::{Material, MeshRenderer, MeshRendererFile};
pub use name::Name;
pub use parent::{KeepPose, Parent};
pub use ray_hit::RayHit;
pub use rigid_body::{BodyKind, LockedAxes, RigidBody};
pub use shading_mode::ShadingMode;
pub use transform::Transform;
