//! [`OffscreenTarget`]: a texture to render into without a window, readable back as an image.

use image::RgbaImage;

use crate::frame::Attachments;
use crate::gpu_context::GpuContext;
use crate::readback_error::ReadbackError;
use crate::render_error::RenderError;
use crate::render_target::sealed::{Sealed, TargetFrame};
use crate::render_target::RenderTarget;

/// Colour format of offscreen targets (sRGB, 8 bits per channel, straight alpha).
pub const OFFSCREEN_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

/// A colour texture of any size ([`OFFSCREEN_FORMAT`]) with its own depth / MSAA buffers.
/// Usable as a render attachment, a copy source and a sampled texture (an editor viewport).
#[derive(Debug)]
pub struct OffscreenTarget {
    texture: wgpu::Texture,
    view: wgpu::TextureView,
    size: (u32, u32),
    attachments: Option<Attachments>,
}

impl OffscreenTarget {
    /// A `width` × `height` target (each side at least 1 pixel).
    #[must_use]
    pub fn new(gpu: &GpuContext, width: u32, height: u32) -> Self {
        let size = (width.max(1), height.max(1));
        let texture = gpu.device().create_texture(&wgpu::TextureDescriptor {
            label: Some("onyx offscreen colour"),
            size: wgpu::Extent3d {
                width: size.0,
                height: size.1,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: OFFSCREEN_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::COPY_SRC
                | wgpu::TextureUsages::TEXTURE_BINDING,
            // The same bytes as plain `Rgba8Unorm`: what egui samples (it expects textures
            // holding sRGB values, not sRGB-aware ones).
            view_formats: &[wgpu::TextureFormat::Rgba8Unorm],
        });
        let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
        Self {
            texture,
            view,
            size,
            attachments: None,
        }
    }

    /// The colour texture (to show it in a UI, or copy it).
    #[must_use]
    pub fn texture(&self) -> &wgpu::Texture {
        &self.texture
    }

    /// A view of the colour texture.
    #[must_use]
    pub fn view(&self) -> &wgpu::TextureView {
        &self.view
    }

    /// A view of the colour as plain `Rgba8Unorm` (the stored sRGB bytes, undecoded): for
    /// samplers that expect sRGB-encoded values, such as egui's.
    #[must_use]
    pub fn encoded_view(&self) -> wgpu::TextureView {
        self.texture.create_view(&wgpu::TextureViewDescriptor {
            format: Some(wgpu::TextureFormat::Rgba8Unorm),
            ..wgpu::TextureViewDescriptor::default()
        })
    }

    /// Copies the colour texture to the CPU and waits for it.
    ///
    /// # Errors
    /// [`ReadbackError`] when the device fails or is lost while mapping.
    pub fn read_image(&self, gpu: &GpuContext) -> Result<RgbaImage, ReadbackError> {
        crate::readback::read_texture(gpu, &self.texture)
    }
}

impl RenderTarget for OffscreenTarget {
    fn size(&self) -> (u32, u32) {
        self.size
    }

    fn format(&self) -> wgpu::TextureFormat {
        OFFSCREEN_FORMAT
    }
}

impl Sealed for OffscreenTarget {
    fn begin_frame(
        &mut self,
        gpu: &GpuContext,
        samples: u32,
    ) -> Result<Option<TargetFrame>, RenderError> {
        let overlay = self.encoded_view();
        let attachments =
            Attachments::ensure(&mut self.attachments, gpu.device(), self.size, samples);
        Ok(Some(TargetFrame {
            color: self.view.clone(),
            overlay,
            overlay_format: OFFSCREEN_FORMAT.remove_srgb_suffix(),
            depth: attachments.depth.clone(),
            hdr: attachments.hdr.clone(),
            resolve: attachments.resolve.clone(),
            format: OFFSCREEN_FORMAT,
            samples,
            surface_texture: None,
        }))
    }

    fn end_frame(&mut self, _gpu: &GpuContext, _frame: TargetFrame) {}
}
