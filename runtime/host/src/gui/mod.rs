//! Plugin GUIs on the host: each plugin runs egui in its own image; the host feeds it input,
//! gathers its meshes and textures, keeps the input its UI takes from the scene, and paints
//! everything over the scene (or around the scene viewport a plugin shows).
//!
//! - `gui_system.rs`: [`GuiSystem`], per-frame input, outputs, routing, widget lookup.
//! - `gui_frame.rs`: [`GuiFrame`], what to paint this frame.
//! - `gui_input_builder.rs`: [`GuiInputBuilder`], host input events → `egui::RawInput`.
//! - `egui_keys.rs`: Onyx keys and buttons as egui's.
//! - `input_sanitizer.rs`: input numbers no device sends, dropped or brought into range.
//! - `gui_textures.rs`: [`GuiTextures`], plugin textures under host-unique ids.
//! - `gui_painter.rs`: [`GuiPainter`], egui-wgpu drawing over a rendered frame.
//! - `viewport_request.rs`: where a plugin shows the scene viewport.
//! - `widget_query.rs`: a widget's rectangle by label, from the AccessKit tree.

mod egui_keys;
mod gui_frame;
mod gui_input_builder;
mod gui_painter;
mod gui_system;
mod gui_textures;
pub(crate) mod input_sanitizer;
mod viewport_request;
mod widget_query;

pub use gui_frame::GuiFrame;
pub use gui_input_builder::{GuiInputBuilder, DEFAULT_SCREEN_SIZE};
pub use gui_painter::GuiPainter;
pub use gui_system::GuiSystem;
pub use gui_textures::{GuiTexture, GuiTextures, HOST_VIEWPORT_TEXTURE};
