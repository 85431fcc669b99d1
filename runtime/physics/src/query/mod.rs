//! Scene queries: [`RayHit`], [`QueryFilter`] and the `PhysicsWorld` query methods
//! (`cast_ray`, `cast_ray_all`, `intersect_shape`, `intersect_aabb` in `world_queries.rs`;
//! `cast_shape` and [`ShapeHit`] in [`shape_cast`]).

pub mod query_filter;
pub mod ray_hit;
pub mod shape_cast;
mod world_queries;

pub use query_filter::QueryFilter;
pub use ray_hit::RayHit;
pub use shape_cast::{ShapeHit, SHAPE_CAST_MAX_ITERATIONS, SHAPE_CAST_TOLERANCE};
