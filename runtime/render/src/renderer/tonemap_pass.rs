//! Stage 4 of [`Renderer::render`]: the resolved HDR frame through exposure and tone mapping
//! into the target's colour (sRGB-encoded by the target format, or by the shader).

use super::Renderer;
use crate::pipeline::{PipelineKey, ShaderKind};
use crate::render_target::sealed::TargetFrame;

impl Renderer {
    pub(super) fn encode_tonemap(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        frame: &TargetFrame,
    ) {
        let device = self.gpu.device().clone();
        let key = PipelineKey {
            format: frame.format,
            samples: 1,
            ..PipelineKey::scene(ShaderKind::Tonemap, 1)
        };
        if self.pipelines.get(&device, key).is_none() {
            return;
        }
        let hdr = frame.resolve.as_ref().unwrap_or(&frame.hdr);
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("onyx tone mapping"),
            layout: &self.pipelines.layouts().tonemap,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: self.frame_buffer.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: wgpu::BindingResource::TextureView(hdr),
                },
            ],
        });
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("onyx tone mapping"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &frame.color,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: None,
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        if let Some(pipeline) = self.pipelines.cached(&key) {
            pass.set_pipeline(pipeline);
        }
        pass.set_bind_group(0, &group, &[]);
        pass.draw(0..3, 0..1);
    }
}
