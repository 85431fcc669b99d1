//! [`GuiPainter`]: paints a [`GuiFrame`] over a rendered frame with egui-wgpu, uploading the
//! host's egui textures when they change and binding the scene viewport texture.

use std::collections::HashMap;

use egui::epaint::{ClippedPrimitive, ImageDelta, Primitive};
use egui::TextureId;
use onyx_render::{wgpu, Overlay};

use super::gui_frame::GuiFrame;
use super::gui_textures::{GuiTextures, HOST_VIEWPORT_TEXTURE};

/// An egui-wgpu renderer for one colour format, with what it has uploaded.
pub struct GuiPainter {
    renderer: egui_wgpu::Renderer,
    format: wgpu::TextureFormat,
    uploaded: HashMap<TextureId, u64>,
    /// The scene viewport as registered with egui-wgpu, and the generation of the texture.
    viewport: Option<(TextureId, u64)>,
}

impl std::fmt::Debug for GuiPainter {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("GuiPainter")
            .field("format", &self.format)
            .field("textures", &self.uploaded.len())
            .finish()
    }
}

impl GuiPainter {
    /// A painter drawing into targets of `format`. No dithering, so images are
    /// deterministic.
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        let options = egui_wgpu::RendererOptions {
            msaa_samples: 1,
            depth_stencil_format: None,
            dithering: false,
            predictable_texture_filtering: false,
        };
        Self {
            renderer: egui_wgpu::Renderer::new(device, format, options),
            format,
            uploaded: HashMap::new(),
            viewport: None,
        }
    }

    /// The colour format it draws into.
    pub fn format(&self) -> wgpu::TextureFormat {
        self.format
    }

    /// Uploads textures that are new or changed since the last call; frees the gone ones.
    fn sync_textures(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        textures: &GuiTextures,
    ) {
        for (id, texture) in textures.textures() {
            if self.uploaded.get(id) == Some(&texture.version) {
                continue;
            }
            let delta = ImageDelta::full(texture.image.clone(), texture.options);
            self.renderer.update_texture(device, queue, *id, &delta);
            self.uploaded.insert(*id, texture.version);
        }
        let renderer = &mut self.renderer;
        self.uploaded.retain(|id, _| {
            let live = textures.textures().contains_key(id);
            if !live {
                renderer.free_texture(id);
            }
            live
        });
    }

    /// Binds `view` (generation `generation`: bumped whenever the scene texture is
    /// recreated) as the scene viewport.
    pub fn bind_viewport(
        &mut self,
        device: &wgpu::Device,
        view: &wgpu::TextureView,
        generation: u64,
    ) {
        match self.viewport {
            Some((_, g)) if g == generation => {}
            Some((id, _)) => {
                self.renderer.update_egui_texture_from_wgpu_texture(
                    device,
                    view,
                    wgpu::FilterMode::Linear,
                    id,
                );
                self.viewport = Some((id, generation));
            }
            None => {
                let id =
                    self.renderer
                        .register_native_texture(device, view, wgpu::FilterMode::Linear);
                self.viewport = Some((id, generation));
            }
        }
    }

    /// Paints `frame` over `overlay`'s target.
    pub fn paint(&mut self, overlay: &mut Overlay<'_>, frame: &GuiFrame, textures: &GuiTextures) {
        self.sync_textures(overlay.device, overlay.queue, textures);
        let substituted;
        let primitives: &[ClippedPrimitive] = match (frame.viewport, self.viewport) {
            (Some(_), Some((id, _))) => {
                substituted = with_viewport_id(&frame.primitives, id);
                &substituted
            }
            _ => &frame.primitives,
        };
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: [overlay.size.0, overlay.size.1],
            pixels_per_point: frame.pixels_per_point,
        };
        let callbacks = self.renderer.update_buffers(
            overlay.device,
            overlay.queue,
            overlay.encoder,
            primitives,
            &screen,
        );
        debug_assert!(
            callbacks.is_empty(),
            "paint callbacks never cross the boundary"
        );
        let mut pass = overlay
            .encoder
            .begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("onyx gui"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: overlay.view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Load,
                        store: wgpu::StoreOp::Store,
                    },
                })],
                ..Default::default()
            })
            .forget_lifetime();
        self.renderer.render(&mut pass, primitives, &screen);
    }
}

/// `primitives` with the well-known viewport id replaced by the painter's own.
fn with_viewport_id(primitives: &[ClippedPrimitive], id: TextureId) -> Vec<ClippedPrimitive> {
    primitives
        .iter()
        .map(|p| {
            let mut p = p.clone();
            if let Primitive::Mesh(mesh) = &mut p.primitive {
                if mesh.texture_id == HOST_VIEWPORT_TEXTURE {
                    mesh.texture_id = id;
                }
            }
            p
        })
        .collect()
}
