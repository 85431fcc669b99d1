//! Stage 1 of [`Renderer::render`]: the frame's shadow views, its uniforms, culling and
//! batching for the camera and every shadow view, and the uploads (objects, instances,
//! shadow views, debug lines). Timed into `RenderStats::cpu_prepare_time`.

use std::time::Instant;

use super::Renderer;
use crate::environment::EnvironmentMaps;
use crate::frame::{
    FrameInputs, FrameUniforms, FrameViews, LineRaw, MeshBounds, ShadowViewRaw, Upload,
};
use crate::frustum::Frustum;
use crate::render_scene::RenderScene;
use crate::render_stats::RenderStats;
use crate::shadow::ShadowPlan;

impl Renderer {
    pub(super) fn prepare(
        &mut self,
        scene: &RenderScene<'_>,
        size: (u32, u32),
        encode_srgb: bool,
        encoder: &mut wgpu::CommandEncoder,
    ) -> RenderStats {
        let start = Instant::now();
        let device = self.gpu.device().clone();
        let queue = self.gpu.queue().clone();
        let aspect = size.0 as f32 / size.1 as f32;
        let camera = &scene.camera;
        let view_proj = camera.relative_view_projection(aspect);

        let anchor = self.shadow_anchor.follow(camera.position);
        let plan = ShadowPlan::new(camera, anchor, aspect, scene.lights, &self.settings);
        let maps_changed = self.shadow_maps.ensure(
            &device,
            self.settings.shadow_resolution,
            plan.cascades.len() as u32,
            self.settings.local_shadow_resolution,
            plan.local_layers,
        );
        if maps_changed {
            self.bindings.rebuild_lighting(
                &device,
                self.pipelines.layouts(),
                &self.shadow_maps,
                &self.environment,
            );
        }
        let uniforms = FrameUniforms::new(&FrameInputs {
            camera,
            view_proj,
            lights: scene.lights,
            settings: &self.settings,
            shadows: &plan,
            size,
            env_max_mip: EnvironmentMaps::max_mip(),
            sky_image: self.environment.from_image,
            encode_srgb,
        });
        queue.write_buffer(&self.frame_buffer, 0, bytemuck::bytes_of(&uniforms));

        let frustum = self.settings.frustum_culling.then(|| {
            Frustum::from_view_projection(
                &(camera.projection.culling_matrix(aspect) * camera.rotation_view()),
            )
        });
        let views = FrameViews {
            origin: camera.position,
            camera: frustum.as_ref(),
            forward: camera.forward(),
            shadows: &plan.frusta,
            missing: self.textures.checker(),
            instancing: self.settings.instancing,
        };
        let meshes = &self.meshes;
        let counts = self.batcher.prepare(scene.objects, &views, |handle| {
            meshes.get(handle).map(|m| MeshBounds {
                center: m.bounds_center,
                radius: m.bounds_radius,
            })
        });

        let mut upload = Upload {
            device: &device,
            belt: &mut self.belt,
            encoder,
        };
        let objects_grew = self
            .object_buffer
            .write(&mut upload, bytemuck::cast_slice(self.batcher.objects()));
        self.index_buffer
            .write(&mut upload, bytemuck::cast_slice(self.batcher.indices()));
        let shadow_views: Vec<ShadowViewRaw> = plan
            .views
            .iter()
            .map(|v| ShadowViewRaw::new(&v.view_proj))
            .collect();
        let views_grew = self
            .shadow_view_buffer
            .write(&mut upload, bytemuck::cast_slice(&shadow_views));
        if objects_grew || views_grew {
            self.bindings.rebuild_buffers(
                &device,
                self.pipelines.layouts(),
                &self.frame_buffer,
                self.object_buffer.buffer(),
                self.shadow_view_buffer.buffer(),
            );
        }

        self.lines.clear();
        let categories = self.settings.debug_categories;
        let width = self.settings.debug_line_width;
        let origin = camera.position;
        self.lines.extend(
            scene
                .debug_lines
                .iter()
                .filter(|line| categories.intersects(line.category))
                .map(|line| LineRaw::new(line, width, origin)),
        );
        let mut upload = Upload {
            device: &device,
            belt: &mut self.belt,
            encoder,
        };
        self.line_buffer
            .write(&mut upload, bytemuck::cast_slice(&self.lines));

        let triangles = self
            .batcher
            .batches()
            .iter()
            .filter_map(|batch| {
                let mesh = self.meshes.get(self.batcher.key(batch.key).mesh)?;
                Some(u64::from(mesh.index_count / 3) * u64::from(batch.instance_count))
            })
            .sum();
        let stats = RenderStats {
            draw_calls: 0,
            shadow_draw_calls: 0,
            shadow_views: plan.views.len() as u32,
            shadow_instances: counts.shadow_instances,
            blended: counts.blended,
            triangles,
            instances: counts.visible,
            culled: counts.culled,
            batches: self.batcher.batches().len() as u32,
            debug_lines: self.lines.len() as u32,
            cpu_prepare_time: start.elapsed(),
            skipped: false,
        };
        self.shadow_plan = plan;
        stats
    }
}
