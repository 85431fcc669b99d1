//! [`screen_ray`]: the world-space ray under a pixel of the view (click-to-select).

use onyx_plugin_api::glam::{Vec2, Vec3};
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
    let inverse = camera.view_projection(size.x / size.y).inverse();
    let ndc_x = 2.0 * point.x / size.x - 1.0;
    let ndc_y = 1.0 - 2.0 * point.y / size.y;
    // wgpu clip space: depth 0 at the near plane, 1 at the far plane.
    let near = inverse.project_point3(Vec3::new(ndc_x, ndc_y, 0.0));
    let far = inverse.project_point3(Vec3::new(ndc_x, ndc_y, 1.0));
    let direction = (far - near).normalize_or_zero();
    (near.is_finite() && direction != Vec3::ZERO).then_some(Ray {
        origin: near,
        direction,
    })
}
