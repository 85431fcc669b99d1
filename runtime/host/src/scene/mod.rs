//! Scene files: RON, versioned, loaded with line/column errors, saved atomically.
//!
//! - `scene_file.rs`: [`SceneFile`] and [`SceneEntity`], the format (each built-in
//!   component under its key, in its file form; parents by file-local id).
//! - `scene_imports.rs`: [`ImportSettingsFile`], a model's scale, up axis and normals as
//!   the scene's `imports` table gives them.
//! - `scene_read.rs`: parse and check (version, physics, scene graph).
//! - `scene_migrate.rs`: older formats brought to the current one as they are read.
//! - `scene_spawn.rs`: spawn into a world, every value checked first.
//! - `scene_save.rs`: capture a world, atomic write.
//! - `scene_error.rs`: [`SceneError`].
//! - `gltf_import/`: a glTF file read as a scene (its node tree under one root entity).

pub mod gltf_import;
mod scene_error;
mod scene_file;
mod scene_imports;
mod scene_migrate;
mod scene_read;
mod scene_save;
mod scene_spawn;

pub use gltf_import::{import_gltf_scene, is_gltf_scene, GltfImportError, GltfScene};
pub use scene_error::SceneError;
pub use scene_file::{
    SceneComponent, SceneEntity, SceneFile, OLDEST_SCENE_FORMAT_VERSION, SCENE_FORMAT_VERSION,
};
pub use scene_imports::{ImportSettingsFile, NormalsFile, UpAxisFile};
pub use scene_read::{parse_scene, read_scene, read_scene_with};
pub use scene_save::{scene_from_world, write_scene};
pub use scene_spawn::{spawn_scene, spawn_scene_entities};
