//! [`ViewState`]: what the world is seen through — the camera a plugin chose, the orbit
//! camera used when none is, and the view switches tools set.

use onyx_plugin_api::tools::RenderOverrides;
use onyx_plugin_api::Entity;

use super::OrbitCamera;

/// How the world is looked at, kept between frames.
#[derive(Clone, Debug, Default)]
pub struct ViewState {
    /// The camera entity chosen with `Ctx::set_camera`.
    pub camera_override: Option<Entity>,
    /// The view used when no camera is chosen or active.
    pub orbit: OrbitCamera,
    /// The view switches tools set (grid, physics lines, shading of the whole view).
    pub overrides: RenderOverrides,
}
