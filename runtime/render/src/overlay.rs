//! [`Overlay`]: what a caller gets to draw over a rendered frame (a user interface) before
//! it is presented.

/// The finished scene of one frame, open for drawing on top: record passes into `encoder`
/// that load (not clear) `view`. Given by [`Renderer::render_with_overlay`](crate::Renderer::render_with_overlay).
#[derive(Debug)]
pub struct Overlay<'a> {
    /// The device.
    pub device: &'a wgpu::Device,
    /// The queue (for uploads before the encoder is submitted).
    pub queue: &'a wgpu::Queue,
    /// The frame's command encoder; the scene's pass is already recorded.
    pub encoder: &'a mut wgpu::CommandEncoder,
    /// The target's colour (resolved, single-sampled), viewed without sRGB encoding where
    /// the target allows it: egui blends in sRGB space and writes encoded values.
    pub view: &'a wgpu::TextureView,
    /// The colour format of `view`.
    pub format: wgpu::TextureFormat,
    /// The target's size in pixels.
    pub size: (u32, u32),
}
