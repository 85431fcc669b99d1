//! Scene queries: [`RayHit`], [`QueryFilter`] and the `PhysicsWorld` query methods
//! (`cast_ray`, `cast_ray_all`, `intersect_shape`, `intersect_aabb`).

pub mod query_filter;
pub mod ray_hit;
mod world_queries;

pub use query_filter::QueryFilter;
pub use ray_hit::RayHit;
