//! Components: plain data attached to entities.
//!
//! - `name.rs`, `transform.rs`: the built-in components for every entity.
//! - `mesh_renderer.rs` ([`MeshRenderer`], [`Material`]), `mesh_id.rs` ([`MeshId`],
//!   [`TextureId`]), `shading_mode.rs`, `camera.rs`, `light.rs`: what the renderer draws.
//! - `debug_line.rs`: [`DebugLine`], one frame's debug drawing.
//! - `rigid_body.rs` ([`RigidBody`], [`BodyKind`], [`LockedAxes`]), `collider.rs`
//!   ([`Collider`], [`ColliderShape`]), `ray_hit.rs` ([`RayHit`]): physics.
//! - `component.rs`: [`Component`], a plugin's own serde component.
//! - `component_type.rs`: [`ComponentType`], what `Ctx::get`/`set`/`remove` accept.
//! - `bundle.rs`: [`Bundle`], components spawned together.
//! - `entity_transform.rs`, `blob_format.rs`: rows of bulk queries, raw-blob encodings.

mod blob_format;
mod bundle;
mod camera;
mod collider;
#[allow(clippy::module_inception)]
mod component;
pub(crate) mod component_type;
mod debug_line;
mod entity_transform;
mod light;
mod mesh_id;
mod mesh_renderer;
mod name;
mod ray_hit;
mod rigid_body;
mod shading_mode;
mod transform;

pub use blob_format::BlobFormat;
pub use bundle::Bundle;
pub use camera::{Camera, Projection};
pub use collider::{Collider, ColliderShape};
pub use component::Component;
pub use component_type::ComponentType;
pub use debug_line::DebugLine;
pub use entity_transform::EntityTransform;
pub use light::Light;
pub use mesh_id::{MeshId, TextureId};
pub use mesh_renderer::{Material, MeshRenderer};
pub use name::Name;
pub use ray_hit::RayHit;
pub use rigid_body::{BodyKind, LockedAxes, RigidBody};
pub use shading_mode::ShadingMode;
pub use transform::Transform;
