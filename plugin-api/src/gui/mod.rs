//! GUI across the boundary: each plugin draws with its own [`egui`] context in
//! [`Plugin::draw_gui`](crate::Plugin::draw_gui); the host renders the result over the scene.
//!
//! The scene itself can be shown inside the UI: an image of [`VIEWPORT_TEXTURE`] (most simply
//! [`viewport`]) makes the host draw the scene into a texture of exactly the image's size in
//! pixels instead of over the whole window, and pointer input over that image goes to the
//! scene rather than to the UI.
//!
//! ```
//! use onyx_plugin_api::{egui, gui, Ctx, Plugin};
//!
//! struct Editor;
//! impl Plugin for Editor {
//!     fn draw_gui(&mut self, _ctx: &mut Ctx, ui: &mut egui::Ui) {
//!         egui::Panel::left("outline").show(ui, |ui| {
//!             ui.label("Scene");
//!         });
//!         egui::CentralPanel::default().show(ui, |ui| {
//!             gui::viewport(ui);
//!         });
//!     }
//! }
//! ```

/// The texture id of the scene viewport: an image with this texture shows what the scene's
/// camera sees, rendered by the host at the image's size (one frame later after a resize).
pub const VIEWPORT_TEXTURE: egui::TextureId = egui::TextureId::User(u64::MAX);

/// Shows the scene viewport filling the space left in `ui`; the response senses clicks and
/// drags (the host's scene input gets the same pointer events).
pub fn viewport(ui: &mut egui::Ui) -> egui::Response {
    let size = ui.available_size();
    viewport_sized(ui, size)
}

/// Shows the scene viewport at `size` points.
pub fn viewport_sized(ui: &mut egui::Ui, size: egui::Vec2) -> egui::Response {
    ui.add(
        egui::Image::new(egui::load::SizedTexture::new(VIEWPORT_TEXTURE, size))
            .sense(egui::Sense::click_and_drag()),
    )
}
