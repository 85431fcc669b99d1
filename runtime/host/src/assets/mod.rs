//! Assets: which file each mesh and texture id stands for, shared by rendering, physics
//! (mesh colliders), scenes and tools.
//!
//! - `asset_registry.rs`: [`AssetRegistry`], ids ↔ files (no GPU needed).

mod asset_registry;

pub use asset_registry::AssetRegistry;
