//! What the host keeps for the tool services (the editor's needs) between plugin calls.
//!
//! - `tool_state.rs`: [`ToolState`]: diagnostics, the plugin list, play mode, scripts, the
//!   open scene's path.
//! - `scene_pick.rs`: [`pick`], the entity a ray meets by what it shows, and
//!   [`local_bounds`]; `mesh_bounds.rs`: [`MeshBounds`], the meshes' shapes they use.

mod mesh_bounds;
mod scene_pick;
mod tool_state;

pub use mesh_bounds::MeshBounds;
pub use scene_pick::{local_bounds, pick};
pub use tool_state::ToolState;
