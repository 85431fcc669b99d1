//! Broadphase: [`DynamicTree`] of enlarged boxes and [`BroadPhase`] pair finding.

pub mod broad_phase;
pub mod dynamic_tree;

pub use broad_phase::BroadPhase;
pub use dynamic_tree::DynamicTree;
