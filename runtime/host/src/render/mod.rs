//! Drawing the world: onyx-render fed from the ECS.
//!
//! - `render_system.rs`: [`RenderSystem`], the renderer and the per-frame scene it draws from
//!   a `RenderInput`.
//! - `render_assets.rs`: `RenderAssets`, the GPU copies of the registered models and textures,
//!   loaded on worker threads and uploaded by the frame when done.
//! - `render_with_gui.rs`: the scene and the plugins' GUIs drawn together (`GuiGpu` per
//!   renderer).
//! - `previous_pose.rs`: `PreviousPose`, world poses of the previous fixed step, for
//!   interpolation.
//! - `view_state.rs`: `ViewState`, the chosen camera, the orbit camera, the view switches;
//!   `orbit_camera.rs`: `OrbitCamera`, the view when the scene has no camera.
//! - `screenshot.rs`: saving a PNG, [`ScreenshotError`].
//! - `active_camera.rs`: `active_camera`, the camera the world is seen through;
//!   `screen_ray.rs`: `screen_ray`, the ray under a pixel (click-to-select).
//! - `asset_watcher.rs`: `AssetWatcher`, notices edited model and texture files (hot reload).
//! - `shader_watcher.rs`: `ShaderWatcher`, recompiles edited shaders (hot reload), and
//!   `shader_dir`, the source checkout's shader folder.

mod active_camera;
mod asset_watcher;
mod orbit_camera;
pub(crate) mod previous_pose;
mod render_assets;
mod render_system;
mod render_with_gui;
mod screen_ray;
mod screenshot;
mod shader_watcher;
mod view_state;

pub(crate) use active_camera::active_camera;
pub(crate) use orbit_camera::OrbitCamera;
pub(crate) use previous_pose::PreviousPose;
pub use render_system::RenderSystem;
pub(crate) use render_system::{drawn_poses, RenderInput};
pub(crate) use render_with_gui::{render_image_with_gui, render_with_gui, GuiGpu};
pub(crate) use screen_ray::screen_ray;
pub use screenshot::{save_png, ScreenshotError};
pub(crate) use shader_watcher::{shader_dir, ShaderWatcher};
pub(crate) use view_state::ViewState;
