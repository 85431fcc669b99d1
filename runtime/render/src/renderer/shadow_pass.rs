//! Stage 2 of [`Renderer::render`]: one depth pass per shadow view of the frame's
//! [`crate::shadow::ShadowPlan`], each drawing its casters instanced from the shared object
//! buffer (the view's matrix at a dynamic offset).

use super::Renderer;
use crate::frame::{AlphaClass, MaterialMaps, SHADOW_VIEW_STRIDE};
use crate::pipeline::{PipelineKey, ShaderKind};
use crate::shadow::{ShadowTarget, SHADOW_FORMAT};

impl Renderer {
    /// Records every shadow pass; returns their draw calls.
    pub(super) fn encode_shadows(&mut self, encoder: &mut wgpu::CommandEncoder) -> u32 {
        let views = self.shadow_plan.views.len();
        if views == 0 {
            return 0;
        }
        let device = self.gpu.device().clone();
        let key_of = |masked: bool, double_sided: bool| PipelineKey {
            kind: ShaderKind::Shadow,
            format: SHADOW_FORMAT,
            samples: 1,
            alpha: if masked {
                AlphaClass::Mask
            } else {
                AlphaClass::Opaque
            },
            double_sided,
        };
        for view in 0..views {
            for batch in self.batcher.shadow_batches(view) {
                let key = self.batcher.shadow_key(batch.key);
                let _ = self
                    .pipelines
                    .get(&device, key_of(key.masked, key.double_sided));
                if key.masked {
                    let maps = MaterialMaps {
                        base_color: key.mask_texture,
                        ..MaterialMaps::default()
                    };
                    let _ = self.textures.material_group(
                        &device,
                        &self.pipelines.layouts().material,
                        &maps,
                    );
                }
            }
        }
        let mut draws = 0;
        for (index, shadow_view) in self.shadow_plan.views.iter().enumerate() {
            let target = match shadow_view.target {
                ShadowTarget::Cascade(layer) => {
                    self.shadow_maps.directional.layer_views.get(layer as usize)
                }
                ShadowTarget::Local(layer) => {
                    self.shadow_maps.local.layer_views.get(layer as usize)
                }
            };
            let Some(target) = target else { continue };
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("onyx shadow pass"),
                color_attachments: &[],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: target,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Store,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            let batches = self.batcher.shadow_batches(index);
            if batches.is_empty() {
                continue;
            }
            let offset = (index as u64 * SHADOW_VIEW_STRIDE) as u32;
            pass.set_bind_group(0, &self.bindings.shadow_view, &[offset]);
            pass.set_vertex_buffer(1, self.index_buffer.buffer().slice(..));
            let mut current = None;
            for batch in batches {
                let key = self.batcher.shadow_key(batch.key);
                let pipeline_key = key_of(key.masked, key.double_sided);
                let Some(pipeline) = self.pipelines.cached(&pipeline_key) else {
                    continue;
                };
                if current != Some(pipeline_key) {
                    pass.set_pipeline(pipeline);
                    current = Some(pipeline_key);
                }
                let Some(mesh) = self.meshes.get(key.mesh) else {
                    continue;
                };
                if key.masked {
                    let maps = MaterialMaps {
                        base_color: key.mask_texture,
                        ..MaterialMaps::default()
                    };
                    if let Some(group) = self.textures.cached_material_group(&maps) {
                        pass.set_bind_group(1, group, &[]);
                    }
                }
                pass.set_vertex_buffer(0, mesh.vertex_buffer.slice(..));
                pass.set_index_buffer(mesh.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(
                    0..mesh.index_count,
                    0,
                    batch.first_instance..batch.first_instance + batch.instance_count,
                );
                draws += 1;
            }
        }
        draws
    }
}
