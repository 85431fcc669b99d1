//! Stage 3 of [`Renderer::render`]: the HDR scene pass — opaque and masked batches, the sky
//! where nothing was drawn, the grid, blended batches back to front, debug lines.

use super::Renderer;
use crate::frame::{AlphaClass, BatchKey, MaterialMaps};
use crate::pipeline::{PipelineKey, ShaderKind};
use crate::render_target::sealed::TargetFrame;
use crate::shading_mode::ShadingMode;

/// Vertices of the fullscreen triangle that draws the grid and the sky.
const FULLSCREEN_VERTICES: u32 = 3;
/// Vertices of the quad that draws one debug line.
const LINE_VERTICES: u32 = 6;

/// The pipeline of a camera batch.
fn pipeline_of(key: &BatchKey, samples: u32) -> PipelineKey {
    if key.placeholder {
        return PipelineKey::scene(ShaderKind::Placeholder, samples)
            .with_alpha(AlphaClass::Opaque, key.double_sided);
    }
    let alpha = if key.shading.uses_alpha() {
        key.alpha
    } else {
        AlphaClass::Opaque
    };
    PipelineKey::scene(ShaderKind::Mesh(key.shading), samples).with_alpha(alpha, key.double_sided)
}

impl Renderer {
    /// Records the pass; returns the number of draw calls.
    pub(super) fn encode_scene(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        frame: &TargetFrame,
        grid: bool,
    ) -> u32 {
        let samples = frame.samples;
        let draw_grid = grid && self.settings.grid;
        let draw_sky = self.settings.sky_background;
        let draw_lines = !self.lines.is_empty();

        // Build (or fetch) every pipeline and material group the frame needs first.
        let device = self.gpu.device().clone();
        for batch in self.batcher.batches() {
            let key = self.batcher.key(batch.key);
            let _ = self.pipelines.get(&device, pipeline_of(&key, samples));
            if uses_material(&key) {
                let _ = self.textures.material_group(
                    &device,
                    &self.pipelines.layouts().material,
                    &key.maps,
                );
            }
        }
        let _ = self.textures.material_group(
            &device,
            &self.pipelines.layouts().material,
            &MaterialMaps::default(),
        );
        for (wanted, kind) in [
            (draw_grid, ShaderKind::Grid),
            (draw_sky, ShaderKind::Sky),
            (draw_lines, ShaderKind::DebugLines),
        ] {
            if wanted {
                let _ = self
                    .pipelines
                    .get(&device, PipelineKey::scene(kind, samples));
            }
        }

        let clear = if draw_sky {
            [0.0, 0.0, 0.0, 1.0]
        } else {
            self.settings.clear_color
        };
        let (view, resolve_target) = (&frame.hdr, frame.resolve.as_ref());
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("onyx scene pass"),
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
                    store: if resolve_target.is_some() {
                        wgpu::StoreOp::Discard
                    } else {
                        wgpu::StoreOp::Store
                    },
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &frame.depth,
                depth_ops: Some(wgpu::Operations {
                    // Reverse-Z: 0 is infinitely far.
                    load: wgpu::LoadOp::Clear(0.0),
                    store: wgpu::StoreOp::Discard,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_bind_group(0, &self.bindings.frame, &[]);
        let mut draws = 0;
        if !self.batcher.indices().is_empty() {
            pass.set_vertex_buffer(1, self.index_buffer.buffer().slice(..));
        }
        let batches = self.batcher.batches();
        let first_blended = batches
            .iter()
            .position(|b| {
                let key = self.batcher.key(b.key);
                key.alpha == AlphaClass::Blend && key.shading.uses_alpha()
            })
            .unwrap_or(batches.len());
        let default_maps = MaterialMaps::default();

        let mut current: Option<PipelineKey> = None;
        let draw_batches = |pass: &mut wgpu::RenderPass<'_>,
                            range: std::ops::Range<usize>,
                            current: &mut Option<PipelineKey>| {
            let mut count = 0;
            for batch in &batches[range] {
                let key = self.batcher.key(batch.key);
                let pipeline_key = pipeline_of(&key, samples);
                let Some(pipeline) = self.pipelines.cached(&pipeline_key) else {
                    continue;
                };
                if *current != Some(pipeline_key) {
                    pass.set_pipeline(pipeline);
                    *current = Some(pipeline_key);
                }
                let Some(mesh) = self.meshes.get(key.mesh) else {
                    continue;
                };
                let instances = batch.first_instance..batch.first_instance + batch.instance_count;
                if key.shading == ShadingMode::Wireframe && !key.placeholder {
                    // One vertex per index, pulled from the mesh's own buffers (no copy).
                    pass.set_bind_group(1, &mesh.wire_bind_group, &[]);
                    pass.draw(0..mesh.index_count, instances);
                } else {
                    if uses_material(&key) {
                        let maps = if key.placeholder {
                            &default_maps
                        } else {
                            &key.maps
                        };
                        if let Some(group) = self.textures.cached_material_group(maps) {
                            pass.set_bind_group(1, group, &[]);
                        }
                        if key.placeholder || key.shading != ShadingMode::Unlit {
                            pass.set_bind_group(2, &self.bindings.lighting, &[]);
                        }
                    }
                    pass.set_vertex_buffer(0, mesh.vertex_buffer.slice(..));
                    pass.set_index_buffer(mesh.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
                    pass.draw_indexed(0..mesh.index_count, 0, instances);
                }
                count += 1;
            }
            count
        };
        draws += draw_batches(&mut pass, 0..first_blended, &mut current);
        for (wanted, kind) in [(draw_sky, ShaderKind::Sky), (draw_grid, ShaderKind::Grid)] {
            if !wanted {
                continue;
            }
            if let Some(pipeline) = self.pipelines.cached(&PipelineKey::scene(kind, samples)) {
                pass.set_pipeline(pipeline);
                current = None;
                if kind == ShaderKind::Sky {
                    // The lit layout (an image sky reads its cube from the lighting group); the
                    // neutral maps fill group 1.
                    if let Some(group) = self.textures.cached_material_group(&default_maps) {
                        pass.set_bind_group(1, group, &[]);
                    }
                    pass.set_bind_group(2, &self.bindings.lighting, &[]);
                }
                pass.draw(0..FULLSCREEN_VERTICES, 0..1);
                draws += 1;
            }
        }
        draws += draw_batches(&mut pass, first_blended..batches.len(), &mut current);
        if draw_lines {
            if let Some(pipeline) = self
                .pipelines
                .cached(&PipelineKey::scene(ShaderKind::DebugLines, samples))
            {
                pass.set_pipeline(pipeline);
                pass.set_vertex_buffer(0, self.line_buffer.buffer().slice(..));
                pass.draw(0..LINE_VERTICES, 0..self.lines.len() as u32);
                draws += 1;
            }
        }
        draws
    }
}

/// Whether a batch binds material maps and lighting (groups 1 and 2).
fn uses_material(key: &BatchKey) -> bool {
    key.placeholder
        || matches!(
            key.shading,
            ShadingMode::Unlit | ShadingMode::Lit | ShadingMode::LitLow
        )
}
