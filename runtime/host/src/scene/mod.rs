//! Scene files: RON, versioned, loaded with line/column errors, saved atomically.
//!
//! - `scene_file.rs`: [`SceneFile`], the format.
//! - `scene_physics.rs`: [`ScenePhysics`], the physics preset and overrides a scene asks for.
//! - `scene_io.rs`: parse, spawn into a world, capture from a world, atomic write.
//! - `scene_error.rs`: [`SceneError`].

mod scene_error;
mod scene_file;
mod scene_io;
mod scene_physics;

pub use scene_error::SceneError;
pub use scene_file::{
    SceneCollider, SceneComponent, SceneEntity, SceneFile, SceneMeshRenderer, SceneShape,
    SCENE_FORMAT_VERSION,
};
pub use scene_io::{
    parse_scene, read_scene, scene_collider, scene_from_world, scene_mesh_renderer, spawn_scene,
    write_atomically, write_scene,
};
pub use scene_physics::{ScenePhysics, MAX_SCENE_FIXED_HZ, MAX_SCENE_SUBSTEPS};
