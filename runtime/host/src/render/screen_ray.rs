//! [`screen_ray`]: the world-space ray under a pixel of the view (click-to-select).

use onyx_plugin_api::glam::Vec2;
use onyx_plugin_api::tools::Ray;

use super::{active_camera, ViewState};
use crate::world::WorldState;

/// The ray through `point` (pixels from the top-left corner) of a `size`-pixel view of the
/// active camera: from the near plane, along the view. `None` outside the view or for an
/// empty or non-finite view.
pub fn screen_ray(world: &WorldState, view: &ViewState, point: Vec2, size: Vec2) -> Option<Ray> {
    if !(point.is_finite() && size.is_finite() && size.x >= 1.0 && size.y >= 1.0) {
        return None;
    }
    if point.x < 0.0 || point.y < 0.0 || point.x > size.x || point.y > size.y {
        return None;
    }
    let camera = active_camera(world, view);
    let ndc_x = 2.0 * point.x / size.x - 1.0;
    let ndc_y = 1.0 - 2.0 * point.y / size.y;
    let (origin, direction) = camera.ray(ndc_x, ndc_y, size.x / size.y)?;
    Some(Ray { origin, direction })
}
