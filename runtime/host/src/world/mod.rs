//! The world plugins see: hecs entities with the built-in components and plugin data, the
//! scene graph over them, and the assets they name.
//!
//! - `world_state.rs`: `WorldState`, the world and the writes that keep its scene graph in
//!   step; `world_refs.rs`: `WorldRefs`, lookups for component checks and file forms.
//! - `builtin_storage.rs`: built-in components in hecs by id or value, through the one list.
//! - `plugin_components.rs`: [`PluginComponents`], named plugin data per entity.

pub(crate) mod builtin_storage;
mod plugin_components;
mod world_refs;
mod world_state;

pub use plugin_components::{PluginComponents, StoredBlob};
pub(crate) use world_refs::WorldRefs;
pub(crate) use world_state::{WorldState, ZeroScaleParent};
