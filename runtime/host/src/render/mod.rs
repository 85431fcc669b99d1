//! Drawing the world: onyx-render fed from the ECS.
//!
//! - `render_system.rs`: [`RenderSystem`], the renderer and the per-frame scene it draws.
//! - `asset_registry.rs`: [`AssetRegistry`], mesh and texture ids ↔ files (no GPU needed).
//! - `previous_transform.rs`: poses of the previous fixed step, for interpolation.
//! - `orbit_camera.rs`: [`OrbitCamera`], the view when the scene has no camera.
//! - `screenshot.rs`: rendering offscreen and saving a PNG.
//! - `active_camera.rs`: [`active_camera`], the camera the world is seen through;
//!   `screen_ray.rs`: [`screen_ray`], the ray under a pixel (click-to-select).
//! - `shader_watcher.rs`: [`ShaderWatcher`], recompiles edited shaders (hot reload).

mod active_camera;
mod asset_registry;
mod orbit_camera;
pub mod previous_transform;
mod render_system;
mod screen_ray;
mod screenshot;
mod shader_watcher;

pub use active_camera::active_camera;
pub use asset_registry::AssetRegistry;
pub use orbit_camera::OrbitCamera;
pub use render_system::RenderSystem;
pub use screen_ray::screen_ray;
pub use screenshot::{render_image, save_png, ScreenshotError};
pub use shader_watcher::ShaderWatcher;
