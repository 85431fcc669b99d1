//! [`SurfaceTarget`]: a window surface to render into (resize, minimise, vsync).

use image::RgbaImage;

use crate::frame::Attachments;
use crate::gpu_context::GpuContext;
use crate::readback_error::ReadbackError;
use crate::render_error::RenderError;
use crate::render_target::sealed::{Sealed, TargetFrame};
use crate::render_target::RenderTarget;
use crate::surface_target_error::SurfaceTargetError;

/// A window's surface. The host creates the `wgpu::Surface` from its window with
/// [`GpuContext::instance`] and calls [`SurfaceTarget::resize`] on every window resize; a
/// 0 × 0 size (minimised) makes [`crate::Renderer::render`] skip frames.
#[derive(Debug)]
pub struct SurfaceTarget {
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    attachments: Option<Attachments>,
    /// Set when the surface must be configured again before the next frame.
    needs_configure: bool,
    /// Capture the next presented frame.
    screenshot_requested: bool,
    /// The captured frame, until taken.
    screenshot: Option<Result<RgbaImage, ReadbackError>>,
}

impl SurfaceTarget {
    /// Wraps `surface` (made from this context's instance) at `width` × `height` pixels.
    /// Picks an sRGB format when offered; `vsync` chooses the present mode.
    ///
    /// # Errors
    /// [`SurfaceTargetError::Unsupported`] when the adapter cannot present to the surface.
    pub fn new(
        gpu: &GpuContext,
        surface: wgpu::Surface<'static>,
        width: u32,
        height: u32,
        vsync: bool,
    ) -> Result<Self, SurfaceTargetError> {
        let caps = surface.get_capabilities(gpu.adapter());
        let Some(&first) = caps.formats.first() else {
            return Err(SurfaceTargetError::Unsupported {
                adapter: gpu.adapter_info().name,
            });
        };
        let format = caps
            .formats
            .iter()
            .copied()
            .find(wgpu::TextureFormat::is_srgb)
            .unwrap_or(first);
        // Overlays (egui) draw through a view of the same texture without sRGB encoding,
        // where the platform lets a surface be viewed so.
        let plain = format.remove_srgb_suffix();
        let view_formats = if plain != format
            && gpu
                .adapter()
                .get_downlevel_capabilities()
                .flags
                .contains(wgpu::DownlevelFlags::SURFACE_VIEW_FORMATS)
        {
            vec![plain]
        } else {
            Vec::new()
        };
        let config = wgpu::SurfaceConfiguration {
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                | (caps.usages & wgpu::TextureUsages::COPY_SRC),
            format,
            color_space: wgpu::SurfaceColorSpace::Auto,
            width,
            height,
            present_mode: present_mode(vsync),
            desired_maximum_frame_latency: 2,
            alpha_mode: caps
                .alpha_modes
                .first()
                .copied()
                .unwrap_or(wgpu::CompositeAlphaMode::Auto),
            view_formats,
        };
        tracing::info!(?format, width, height, vsync, "window surface ready");
        let mut target = Self {
            surface,
            config,
            attachments: None,
            needs_configure: true,
            screenshot_requested: false,
            screenshot: None,
        };
        target.configure(gpu);
        Ok(target)
    }

    /// Follows a window resize. A zero side means minimised: frames are skipped until the
    /// next non-zero size.
    pub fn resize(&mut self, gpu: &GpuContext, width: u32, height: u32) {
        if (width, height) == (self.config.width, self.config.height) {
            return;
        }
        self.config.width = width;
        self.config.height = height;
        self.needs_configure = true;
        self.configure(gpu);
    }

    /// Turns vsync on (`Fifo`-like, no tearing) or off (lowest latency the platform offers).
    pub fn set_vsync(&mut self, gpu: &GpuContext, vsync: bool) {
        let mode = present_mode(vsync);
        if mode != self.config.present_mode {
            self.config.present_mode = mode;
            self.needs_configure = true;
            self.configure(gpu);
        }
    }

    /// Whether vsync is on.
    #[must_use]
    pub fn vsync(&self) -> bool {
        self.config.present_mode == wgpu::PresentMode::AutoVsync
    }

    /// Whether the window is minimised (zero size): frames are skipped.
    #[must_use]
    pub fn is_minimized(&self) -> bool {
        self.config.width == 0 || self.config.height == 0
    }

    /// Asks for a copy of the next frame drawn into the window (taken just before it is
    /// presented); collect it with [`SurfaceTarget::take_screenshot`].
    pub fn request_screenshot(&mut self) {
        self.screenshot_requested = true;
    }

    /// The frame captured after [`SurfaceTarget::request_screenshot`], once it was drawn.
    /// `Err(ReadbackError::NotCopyable)` when the surface does not allow copies.
    pub fn take_screenshot(&mut self) -> Option<Result<RgbaImage, ReadbackError>> {
        self.screenshot.take()
    }

    /// The wrapped surface.
    #[must_use]
    pub fn surface(&self) -> &wgpu::Surface<'static> {
        &self.surface
    }

    fn configure(&mut self, gpu: &GpuContext) {
        if self.is_minimized() || !self.needs_configure {
            return;
        }
        self.surface.configure(gpu.device(), &self.config);
        self.needs_configure = false;
    }
}

fn present_mode(vsync: bool) -> wgpu::PresentMode {
    if vsync {
        wgpu::PresentMode::AutoVsync
    } else {
        wgpu::PresentMode::AutoNoVsync
    }
}

impl RenderTarget for SurfaceTarget {
    fn size(&self) -> (u32, u32) {
        (self.config.width, self.config.height)
    }

    fn format(&self) -> wgpu::TextureFormat {
        self.config.format
    }
}

impl Sealed for SurfaceTarget {
    fn begin_frame(
        &mut self,
        gpu: &GpuContext,
        samples: u32,
    ) -> Result<Option<TargetFrame>, RenderError> {
        if self.is_minimized() {
            return Ok(None);
        }
        self.configure(gpu);
        let (texture, suboptimal) = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(texture) => (texture, false),
            wgpu::CurrentSurfaceTexture::Suboptimal(texture) => (texture, true),
            wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => {
                tracing::debug!("surface not ready, frame skipped");
                return Ok(None);
            }
            wgpu::CurrentSurfaceTexture::Outdated => {
                tracing::debug!("surface outdated, reconfiguring");
                self.needs_configure = true;
                self.configure(gpu);
                return Ok(None);
            }
            wgpu::CurrentSurfaceTexture::Lost => return Err(RenderError::SurfaceLost),
            wgpu::CurrentSurfaceTexture::Validation => return Err(RenderError::SurfaceValidation),
        };
        if suboptimal {
            self.needs_configure = true;
        }
        let size = (self.config.width, self.config.height);
        let attachments = Attachments::ensure(&mut self.attachments, gpu.device(), size, samples);
        let color = texture
            .texture
            .create_view(&wgpu::TextureViewDescriptor::default());
        let overlay_format = self
            .config
            .view_formats
            .first()
            .copied()
            .unwrap_or(self.config.format);
        let overlay = texture.texture.create_view(&wgpu::TextureViewDescriptor {
            format: Some(overlay_format),
            ..wgpu::TextureViewDescriptor::default()
        });
        Ok(Some(TargetFrame {
            color,
            overlay,
            overlay_format,
            depth: attachments.depth.clone(),
            hdr: attachments.hdr.clone(),
            resolve: attachments.resolve.clone(),
            format: self.config.format,
            samples,
            surface_texture: Some(texture),
        }))
    }

    fn end_frame(&mut self, gpu: &GpuContext, frame: TargetFrame) {
        if let Some(texture) = frame.surface_texture {
            if std::mem::take(&mut self.screenshot_requested) {
                self.screenshot = Some(crate::readback::read_texture(gpu, &texture.texture));
            }
            gpu.queue().present(texture);
        }
        // A suboptimal frame still presents; reconfigure before the next one.
        self.configure(gpu);
    }
}
