//! Components: plain data attached to entities.
//!
//! - `name.rs`, `transform.rs`: the built-in components.
//! - `component.rs`: [`Component`], a plugin's own serde component.
//! - `component_type.rs`: [`ComponentType`], what `Ctx::get`/`set`/`remove` accept.
//! - `bundle.rs`: [`Bundle`], components spawned together.
//! - `entity_transform.rs`, `blob_format.rs`: rows of bulk queries, raw-blob encodings.

mod blob_format;
mod bundle;
#[allow(clippy::module_inception)]
mod component;
pub(crate) mod component_type;
mod entity_transform;
mod name;
mod transform;

pub use blob_format::BlobFormat;
pub use bundle::Bundle;
pub use component::Component;
pub use component_type::ComponentType;
pub use entity_transform::EntityTransform;
pub use name::Name;
pub use transform::Transform;
