//! Where a plugin shows the scene viewport: the screen rectangle of the meshes that sample
//! [`VIEWPORT_TEXTURE`](onyx_plugin_api::gui::VIEWPORT_TEXTURE).

use egui::epaint::{ClippedPrimitive, Primitive};
use egui::Rect;

use super::gui_textures::HOST_VIEWPORT_TEXTURE;

/// The rectangle (points, clipped) covered by viewport images in `primitives`, if any.
pub fn viewport_rect(primitives: &[ClippedPrimitive]) -> Option<Rect> {
    let mut found: Option<Rect> = None;
    for primitive in primitives {
        let Primitive::Mesh(mesh) = &primitive.primitive else {
            continue;
        };
        if mesh.texture_id != HOST_VIEWPORT_TEXTURE || mesh.vertices.is_empty() {
            continue;
        }
        let bounds = mesh.calc_bounds().intersect(primitive.clip_rect);
        if bounds.is_positive() {
            found = Some(found.map_or(bounds, |r| r.union(bounds)));
        }
    }
    found
}
