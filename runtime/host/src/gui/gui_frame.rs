//! [`GuiFrame`]: what the plugins' GUIs paint this frame.

use egui::epaint::ClippedPrimitive;
use egui::Rect;

/// What to paint this frame over (or around) the scene.
#[derive(Debug, Default)]
pub struct GuiFrame {
    /// Every plugin's triangles, in plugin order, with host texture ids.
    pub primitives: Vec<ClippedPrimitive>,
    /// Physical pixels per point.
    pub pixels_per_point: f32,
    /// Where a plugin shows the scene viewport (points), if one does.
    pub viewport: Option<Rect>,
}

impl GuiFrame {
    /// The viewport's size in physical pixels, if one is shown.
    pub fn viewport_pixels(&self) -> Option<(u32, u32)> {
        let rect = self.viewport?;
        let w = (rect.width() * self.pixels_per_point).round();
        let h = (rect.height() * self.pixels_per_point).round();
        (w >= 1.0 && h >= 1.0).then_some((w as u32, h as u32))
    }
}
