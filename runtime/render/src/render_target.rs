//! [`RenderTarget`]: what [`crate::Renderer::render`] draws into, an
//! [`crate::OffscreenTarget`] or a [`crate::SurfaceTarget`].

pub(crate) mod sealed {
    use crate::gpu_context::GpuContext;
    use crate::render_error::RenderError;

    /// Views of one frame of a target: the scene is drawn into `hdr` (resolved into
    /// `resolve` with MSAA) with `depth`, then tone-mapped into `color`.
    #[derive(Debug)]
    pub struct TargetFrame {
        pub(crate) color: wgpu::TextureView,
        /// The colour as overlays (egui) draw into it: the same texture, viewed without sRGB
        /// encoding where the target allows (egui blends in sRGB space and writes encoded
        /// values; on an sRGB view it would be decoded twice, and egui-wgpu warns).
        pub(crate) overlay: wgpu::TextureView,
        pub(crate) overlay_format: wgpu::TextureFormat,
        pub(crate) depth: wgpu::TextureView,
        pub(crate) hdr: wgpu::TextureView,
        pub(crate) resolve: Option<wgpu::TextureView>,
        pub(crate) format: wgpu::TextureFormat,
        pub(crate) samples: u32,
        pub(crate) surface_texture: Option<wgpu::SurfaceTexture>,
    }

    /// The part of [`super::RenderTarget`] only this crate implements.
    pub trait Sealed {
        /// Prepares a frame with `samples` MSAA samples; `Ok(None)` skips the frame.
        fn begin_frame(
            &mut self,
            gpu: &GpuContext,
            samples: u32,
        ) -> Result<Option<TargetFrame>, RenderError>;
        /// Finishes a frame after its commands were submitted (presents a surface).
        fn end_frame(&mut self, gpu: &GpuContext, frame: TargetFrame);
    }
}

/// Something the renderer draws into. Implemented by [`crate::OffscreenTarget`] and
/// [`crate::SurfaceTarget`] (sealed).
pub trait RenderTarget: sealed::Sealed {
    /// Size in pixels (0 × 0 for a minimised window).
    fn size(&self) -> (u32, u32);
    /// Colour format.
    fn format(&self) -> wgpu::TextureFormat;
}
