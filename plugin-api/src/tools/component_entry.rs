//! [`ComponentEntry`]: one component of an entity, as its type name and JSON text.

use serde::{Deserialize, Serialize};

/// One component of an entity, as [`Ctx::components_of`](crate::Ctx::components_of) lists it.
///
/// Built-in components are named by their Rust type (`Transform`, `RigidBody`, …; meshes
/// and textures by file path, as scene files write them); plugin components by their
/// [`Component::NAME`](crate::Component::NAME).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ComponentEntry {
    /// The component's type name.
    pub type_name: String,
    /// Whether it is one of the host's built-in components (else a plugin component).
    pub builtin: bool,
    /// Its value as JSON text (raw plugin components: a JSON string of base64).
    pub value: String,
}
