//! The scene graph: [`Parent`](onyx_plugin_api::Parent) components make children, whose
//! [`Transform`](onyx_plugin_api::Transform) is then relative to their parent.
//!
//! - `transform_hierarchy.rs`: [`TransformHierarchy`], the index of parents and children and
//!   every child's world pose, recomputed for changed subtrees only.
//! - `world_pose.rs`: one entity's world pose computed on demand from the components, and
//!   the local transform that puts an entity at a given world pose.

mod transform_hierarchy;
pub(crate) mod world_pose;

pub use transform_hierarchy::TransformHierarchy;
