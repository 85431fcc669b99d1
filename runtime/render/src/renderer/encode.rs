//! Stage 2 of [`Renderer::render`]: records the frame's single render pass (meshes in
//! batches, then the grid, then debug lines).

use super::Renderer;
use crate::frame::BatchKey;
use crate::pipeline::{PipelineKey, ShaderKind};
use crate::render_target::sealed::TargetFrame;
use crate::shading_mode::ShadingMode;

/// Vertices of the fullscreen triangle that draws the grid.
const GRID_VERTICES: u32 = 3;
/// Vertices of the quad that draws one debug line.
const LINE_VERTICES: u32 = 6;

impl Renderer {
    /// Records the pass; returns the number of draw calls.
    pub(super) fn encode(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        frame: &TargetFrame,
        grid: bool,
    ) -> u32 {
        let key = |kind| PipelineKey {
            kind,
            format: frame.format,
            samples: frame.samples,
        };
        let draw_grid = grid && self.settings.grid;
        let draw_lines = !self.lines.is_empty();

        // Build (or fetch) every pipeline this frame needs before the pass starts.
        let device = self.gpu.device().clone();
        let mut last = None;
        for batch in self.batcher.batches() {
            let kind = shader_of(batch.key);
            if last != Some(kind) {
                last = Some(kind);
                let _ = self.pipelines.get(&device, key(kind));
            }
        }
        if draw_grid {
            let _ = self.pipelines.get(&device, key(ShaderKind::Grid));
        }
        if draw_lines {
            let _ = self.pipelines.get(&device, key(ShaderKind::DebugLines));
        }

        let clear = self.settings.clear_color;
        let (view, resolve_target) = match &frame.msaa {
            Some(msaa) => (msaa, Some(&frame.color)),
            None => (&frame.color, None),
        };
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("onyx main pass"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view,
                depth_slice: None,
                resolve_target,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color {
                        r: clear[0],
                        g: clear[1],
                        b: clear[2],
                        a: clear[3],
                    }),
                    store: if frame.msaa.is_some() {
                        wgpu::StoreOp::Discard
                    } else {
                        wgpu::StoreOp::Store
                    },
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &frame.depth,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store: wgpu::StoreOp::Discard,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_bind_group(0, &self.frame_bind_group, &[]);
        let mut draws = 0;

        if !self.batcher.instances().is_empty() {
            pass.set_vertex_buffer(1, self.instance_buffer.buffer().slice(..));
        }
        let mut current: Option<(ShaderKind, bool)> = None;
        for batch in self.batcher.batches() {
            let kind = shader_of(batch.key);
            if current.map(|(k, _)| k) != Some(kind) {
                let pipeline = self.pipelines.cached(&key(kind));
                if let Some(pipeline) = pipeline {
                    pass.set_pipeline(pipeline);
                }
                current = Some((kind, pipeline.is_some()));
            }
            let Some((_, true)) = current else { continue };
            let Some(mesh) = self.meshes.get(batch.key.mesh) else {
                continue;
            };
            if kind == ShaderKind::Mesh(ShadingMode::Lit) {
                let handle = batch.key.texture.unwrap_or(self.textures.white());
                let texture = self
                    .textures
                    .get(handle)
                    .or_else(|| self.textures.get(self.textures.checker()));
                if let Some(texture) = texture {
                    pass.set_bind_group(1, &texture.bind_group, &[]);
                }
            }
            let instances = batch.first_instance..batch.first_instance + batch.instance_count;
            if kind == ShaderKind::Mesh(ShadingMode::Wireframe) {
                // One vertex per index, pulled from the mesh's own buffers (no copy).
                pass.set_bind_group(1, &mesh.wire_bind_group, &[]);
                pass.draw(0..mesh.index_count, instances);
            } else {
                pass.set_vertex_buffer(0, mesh.vertex_buffer.slice(..));
                pass.set_index_buffer(mesh.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..mesh.index_count, 0, instances);
            }
            draws += 1;
        }

        if draw_grid {
            if let Some(pipeline) = self.pipelines.cached(&key(ShaderKind::Grid)) {
                pass.set_pipeline(pipeline);
                pass.draw(0..GRID_VERTICES, 0..1);
                draws += 1;
            }
        }
        if draw_lines {
            if let Some(pipeline) = self.pipelines.cached(&key(ShaderKind::DebugLines)) {
                pass.set_pipeline(pipeline);
                pass.set_vertex_buffer(0, self.line_buffer.buffer().slice(..));
                pass.draw(0..LINE_VERTICES, 0..self.lines.len() as u32);
                draws += 1;
            }
        }
        draws
    }
}

/// The shader a batch is drawn with.
fn shader_of(key: BatchKey) -> ShaderKind {
    if key.placeholder {
        ShaderKind::Placeholder
    } else {
        ShaderKind::Mesh(key.shading)
    }
}
