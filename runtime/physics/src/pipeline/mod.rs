//! Private step stages, each an `impl PhysicsWorld` block in its own file.

mod broadphase_stage;
pub mod ccd;
pub(crate) mod column_supports;
mod contact_report_stage;
pub(crate) mod heavy_on_light;
pub mod joint_stage;
mod jointed_masses;
mod narrowphase_stage;
mod prestep;
mod resting_accelerations;
mod sleep_stage;
mod solve_stage;
pub(crate) mod union_find;
pub(crate) mod writeback_stage;
