//! Drawing the scene and the plugin GUIs together: [`render_with_gui`] (any target) and
//! [`render_image_with_gui`] (offscreen, for screenshots). [`GuiGpu`] is what a render system
//! keeps for it: one painter per colour format and the scene viewport texture.

use onyx_plugin_api::glam::Vec3;
use onyx_render::{
    Camera, Lights, OffscreenTarget, Overlay, RenderError, RenderScene, RenderStats, RenderTarget,
};

use super::{RenderInput, RenderSystem, ScreenshotError};
use crate::gui::{GuiPainter, GuiSystem};

/// The GPU side of plugin GUIs for one render system.
#[derive(Debug, Default)]
pub struct GuiGpu {
    painters: Vec<GuiPainter>,
    /// The scene viewport texture, its view as egui samples it, and its generation
    /// (bumped when recreated).
    viewport: Option<(OffscreenTarget, onyx_render::wgpu::TextureView, u64)>,
    generation: u64,
}

fn painter_for<'p>(
    painters: &'p mut Vec<GuiPainter>,
    device: &onyx_render::wgpu::Device,
    format: onyx_render::wgpu::TextureFormat,
) -> &'p mut GuiPainter {
    let index = match painters.iter().position(|p| p.format() == format) {
        Some(index) => index,
        None => {
            painters.push(GuiPainter::new(device, format));
            painters.len() - 1
        }
    };
    &mut painters[index]
}

/// Draws the world into `target` with the plugins' GUIs over it. When a plugin shows the
/// scene viewport, the scene is drawn into the viewport texture at the size shown, and the
/// target gets the GUI only.
pub fn render_with_gui(
    system: &mut RenderSystem,
    input: RenderInput<'_>,
    events: &mut Vec<onyx_plugin_api::Event>,
    target: &mut impl RenderTarget,
    gui: &GuiSystem,
) -> Result<RenderStats, RenderError> {
    let frame = gui.frame();
    if frame.primitives.is_empty() {
        return system.draw(input, events, target);
    }
    let mut gpu = std::mem::take(&mut system.gui);
    let result = match frame.viewport_pixels() {
        None => system.draw_with_overlay(input, events, target, |overlay| {
            painter_for(&mut gpu.painters, overlay.device, overlay.format).paint(
                overlay,
                frame,
                gui.textures(),
            );
        }),
        Some((width, height)) => {
            let stale = gpu
                .viewport
                .as_ref()
                .is_none_or(|(t, _, _)| t.size() != (width, height));
            if stale {
                gpu.generation += 1;
                let texture = OffscreenTarget::new(system.renderer().gpu(), width, height);
                let view = texture.encoded_view();
                gpu.viewport = Some((texture, view, gpu.generation));
            }
            let GuiGpu {
                painters, viewport, ..
            } = &mut gpu;
            match viewport.as_mut() {
                None => Ok(RenderStats::default()),
                Some((texture, view, generation)) => {
                    let scene = system.draw(input, events, texture);
                    // The window shows the GUI only, on the renderer's clear colour.
                    let lights = Lights::default();
                    let backdrop = RenderScene::new(
                        Camera::perspective_look_at(Vec3::Z, Vec3::ZERO, 1.0, 0.1, 10.0),
                        &lights,
                    )
                    .with_grid(false);
                    let drawn = system.renderer_mut().render_with_overlay(
                        target,
                        &backdrop,
                        |overlay: &mut Overlay<'_>| {
                            let painter = painter_for(painters, overlay.device, overlay.format);
                            painter.bind_viewport(overlay.device, view, *generation);
                            painter.paint(overlay, frame, gui.textures());
                        },
                    );
                    drawn.and(scene)
                }
            }
        }
    };
    system.gui = gpu;
    result
}

/// Draws the world and the plugins' GUIs into a `width` × `height` offscreen image.
pub fn render_image_with_gui(
    system: &mut RenderSystem,
    input: RenderInput<'_>,
    events: &mut Vec<onyx_plugin_api::Event>,
    width: u32,
    height: u32,
    gui: &GuiSystem,
) -> Result<onyx_render::image::RgbaImage, ScreenshotError> {
    let mut target = OffscreenTarget::new(system.renderer().gpu(), width.max(1), height.max(1));
    render_with_gui(system, input, events, &mut target, gui)?;
    Ok(target.read_image(system.renderer().gpu())?)
}
