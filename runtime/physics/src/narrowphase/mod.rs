//! Narrowphase: exact contact generation per shape pair, GJK/EPA, persistent manifolds.

pub mod box_box;
pub mod capsule_contacts;
pub(crate) mod closest_approach;
pub(crate) mod collide;
pub mod contact_manifold;
pub mod contact_pair;
pub mod contact_point;
pub mod convex_convex;
pub mod epa;
pub mod gjk;
pub(crate) mod half_space_contacts;
pub(crate) mod narrow_body;
pub mod narrow_phase;
pub mod narrow_stats;
pub mod pair_hasher;
pub(crate) mod polygon_clip;
pub mod raw_manifold;
pub(crate) mod separating_axis;
pub(crate) mod sphere_box;
pub(crate) mod sphere_sphere;
pub mod trimesh_contacts;

pub use contact_manifold::ContactManifold;
pub use contact_pair::ContactPair;
pub use contact_point::ContactPoint;
pub use epa::{epa_penetration, EpaResult, EpaStatus};
pub use gjk::{gjk_distance, gjk_intersects, GjkResult, GjkStatus};
pub use narrow_phase::NarrowPhase;
pub use narrow_stats::NarrowStats;
