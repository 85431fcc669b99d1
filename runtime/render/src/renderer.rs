//! [`Renderer`]: the one entry point: owns the device, assets and pipelines, and draws a
//! [`RenderScene`] into a [`RenderTarget`].
//!
//! `render` runs named stages: `prepare` (uniforms, culling, batching, uploads; timed) →
//! acquire the target frame → `encode` (one render pass: meshes, grid, debug lines) →
//! submit → present. Asset loading lives in `renderer/assets.rs`, pass recording in
//! `renderer/encode.rs`.

mod assets;
mod encode;

use std::time::Instant;

use crate::builtin_meshes::{BuiltinMeshes, BUILTIN_RINGS, BUILTIN_SEGMENTS};
use crate::frame::{Batcher, FrameUniforms, GrowableBuffer, LineRaw, MeshBounds};
use crate::frustum::Frustum;
use crate::gpu_context::GpuContext;
use crate::graphics_event::GraphicsEvent;
use crate::mesh::{MeshCache, MeshData};
use crate::pipeline::{PipelineLibrary, ShaderReloadError, ShaderSource};
use crate::render_error::RenderError;
use crate::render_scene::RenderScene;
use crate::render_settings::RenderSettings;
use crate::render_stats::RenderStats;
use crate::render_target::RenderTarget;
use crate::renderer_init_error::RendererInitError;
use crate::texture::TextureCache;

/// The renderer. One per device; not tied to a window: render into any number of
/// [`crate::OffscreenTarget`]s and [`crate::SurfaceTarget`]s.
#[derive(Debug)]
pub struct Renderer {
    gpu: GpuContext,
    settings: RenderSettings,
    pipelines: PipelineLibrary,
    textures: TextureCache,
    meshes: MeshCache,
    builtin: BuiltinMeshes,
    frame_buffer: wgpu::Buffer,
    frame_bind_group: wgpu::BindGroup,
    instance_buffer: GrowableBuffer,
    line_buffer: GrowableBuffer,
    batcher: Batcher,
    lines: Vec<LineRaw>,
    stats: RenderStats,
    msaa_warned: bool,
}

impl Renderer {
    /// A renderer on an existing device.
    ///
    /// Shaders come from `settings.shader_dir` when set (a file that fails there falls back
    /// to the embedded copy and is reported as a [`GraphicsEvent::ShaderCompileFailed`]).
    ///
    /// # Errors
    /// [`RendererInitError::Shader`] when an embedded shader does not compile on this device.
    pub fn new(gpu: GpuContext, settings: RenderSettings) -> Result<Self, RendererInitError> {
        let device = gpu.device().clone();
        let source = settings
            .shader_dir
            .clone()
            .map_or_else(ShaderSource::embedded, ShaderSource::from_dir);
        let (pipelines, warnings) = PipelineLibrary::new(&device, source)?;
        for warning in warnings {
            gpu.events().push(shader_event(&warning));
        }
        let textures = TextureCache::new(&device, gpu.queue(), &pipelines.layouts().material);
        let frame_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("onyx frame uniforms"),
            size: size_of::<FrameUniforms>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let frame_bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("onyx frame"),
            layout: &pipelines.layouts().frame,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: frame_buffer.as_entire_binding(),
            }],
        });
        let mut meshes = MeshCache::default();
        let storage = &pipelines.layouts().mesh_storage;
        let builtin = BuiltinMeshes {
            cube: meshes.add(&device, storage, &MeshData::cube(1.0), "onyx cube"),
            sphere: meshes.add(
                &device,
                storage,
                &MeshData::sphere(0.5, BUILTIN_SEGMENTS, BUILTIN_RINGS),
                "onyx sphere",
            ),
            plane: meshes.add(&device, storage, &MeshData::plane(1.0), "onyx plane"),
            capsule: meshes.add(
                &device,
                storage,
                &MeshData::capsule(0.25, 0.5, BUILTIN_SEGMENTS, BUILTIN_RINGS),
                "onyx capsule",
            ),
            cylinder: meshes.add(
                &device,
                storage,
                &MeshData::cylinder(0.5, 1.0, BUILTIN_SEGMENTS),
                "onyx cylinder",
            ),
        };
        let instance_buffer =
            GrowableBuffer::new(&device, wgpu::BufferUsages::VERTEX, "onyx instances");
        let line_buffer =
            GrowableBuffer::new(&device, wgpu::BufferUsages::VERTEX, "onyx debug lines");
        tracing::info!(msaa = settings.msaa_samples, shader_dir = ?settings.shader_dir, "renderer ready");
        Ok(Self {
            gpu,
            settings,
            pipelines,
            textures,
            meshes,
            builtin,
            frame_buffer,
            frame_bind_group,
            instance_buffer,
            line_buffer,
            batcher: Batcher::default(),
            lines: Vec::new(),
            stats: RenderStats::default(),
            msaa_warned: false,
        })
    }

    /// A renderer on a new headless device (see [`GpuContext::new_headless`]).
    ///
    /// # Errors
    /// [`RendererInitError`] when no device is available or a shader fails.
    pub fn new_headless(settings: RenderSettings) -> Result<Self, RendererInitError> {
        Self::new(GpuContext::new_headless()?, settings)
    }

    /// The device.
    #[must_use]
    pub fn gpu(&self) -> &GpuContext {
        &self.gpu
    }

    /// Current settings.
    #[must_use]
    pub fn settings(&self) -> &RenderSettings {
        &self.settings
    }

    /// Replaces the settings. A changed `shader_dir` reloads the shaders from it.
    ///
    /// # Errors
    /// [`ShaderReloadError`] when the shader folder changed and some shaders failed there.
    pub fn set_settings(&mut self, settings: RenderSettings) -> Result<(), ShaderReloadError> {
        let dir_changed = settings.shader_dir != self.settings.shader_dir;
        self.settings = settings;
        self.msaa_warned = false;
        if dir_changed {
            let source = self
                .settings
                .shader_dir
                .clone()
                .map_or_else(ShaderSource::embedded, ShaderSource::from_dir);
            self.pipelines.set_source(source);
            return self.reload_shaders();
        }
        Ok(())
    }

    /// Takes the events queued since the last call (validation errors, device loss, shader
    /// failures). Call once per frame and show them.
    #[must_use]
    pub fn drain_events(&self) -> Vec<GraphicsEvent> {
        self.gpu.drain_events()
    }

    /// Re-reads every shader from the shader folder and recompiles it. A shader that fails
    /// keeps its last good pipelines (and a [`GraphicsEvent::ShaderCompileFailed`] is
    /// queued); the others are replaced. The host calls this when it sees a file change.
    ///
    /// # Errors
    /// [`ShaderReloadError`] listing the shaders that failed.
    pub fn reload_shaders(&mut self) -> Result<(), ShaderReloadError> {
        let failures = self.pipelines.reload(self.gpu.device());
        for failure in &failures {
            self.gpu.events().push(shader_event(failure));
        }
        if failures.is_empty() {
            tracing::info!("shaders reloaded");
            Ok(())
        } else {
            Err(ShaderReloadError { failures })
        }
    }

    /// Counters of the last frame.
    #[must_use]
    pub fn stats(&self) -> RenderStats {
        self.stats
    }

    /// Draws `scene` into `target`. A minimised window or a surface that is not ready skips
    /// the frame (`stats.skipped`); the returned stats are also kept in [`Renderer::stats`].
    ///
    /// # Errors
    /// [`RenderError`] when the window surface is lost or invalid.
    pub fn render(
        &mut self,
        target: &mut impl RenderTarget,
        scene: &RenderScene<'_>,
    ) -> Result<RenderStats, RenderError> {
        self.render_with_overlay(target, scene, |_| {})
    }

    /// Like [`Renderer::render`], then lets `overlay` record passes over the finished scene
    /// (a user interface) before the frame is submitted and presented. `overlay` is not called
    /// when the frame is skipped (minimised window, surface not ready).
    pub fn render_with_overlay(
        &mut self,
        target: &mut impl RenderTarget,
        scene: &RenderScene<'_>,
        overlay: impl FnOnce(&mut crate::Overlay<'_>),
    ) -> Result<RenderStats, RenderError> {
        let size = target.size();
        if size.0 == 0 || size.1 == 0 {
            self.stats = RenderStats {
                skipped: true,
                ..RenderStats::default()
            };
            return Ok(self.stats);
        }
        let samples = self.sample_count(target.format());
        let mut stats = self.prepare(scene, size);
        let Some(frame) = target.begin_frame(&self.gpu, samples)? else {
            self.stats = RenderStats {
                skipped: true,
                ..stats
            };
            return Ok(self.stats);
        };
        let mut encoder =
            self.gpu
                .device()
                .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                    label: Some("onyx frame"),
                });
        stats.draw_calls = self.encode(&mut encoder, &frame, scene.grid);
        overlay(&mut crate::Overlay {
            device: self.gpu.device(),
            queue: self.gpu.queue(),
            encoder: &mut encoder,
            view: &frame.overlay,
            format: frame.overlay_format,
            size,
        });
        self.gpu.queue().submit([encoder.finish()]);
        target.end_frame(&self.gpu, frame);
        self.stats = stats;
        Ok(stats)
    }

    /// Stage 1: frame uniforms, culling, batching, instance and line uploads.
    fn prepare(&mut self, scene: &RenderScene<'_>, size: (u32, u32)) -> RenderStats {
        let start = Instant::now();
        let aspect = size.0 as f32 / size.1 as f32;
        let view_proj = scene.camera.view_projection(aspect);
        let uniforms =
            FrameUniforms::new(&scene.camera, view_proj, scene.lights, &self.settings, size);
        self.gpu
            .queue()
            .write_buffer(&self.frame_buffer, 0, bytemuck::bytes_of(&uniforms));

        let frustum = self
            .settings
            .frustum_culling
            .then(|| Frustum::from_view_projection(&view_proj));
        let meshes = &self.meshes;
        let counts = self.batcher.prepare(
            scene.objects,
            self.textures.checker(),
            frustum.as_ref(),
            |handle| {
                meshes.get(handle).map(|m| MeshBounds {
                    center: m.bounds_center,
                    radius: m.bounds_radius,
                })
            },
            self.settings.instancing,
        );
        self.instance_buffer.write(
            self.gpu.device(),
            self.gpu.queue(),
            bytemuck::cast_slice(self.batcher.instances()),
        );

        self.lines.clear();
        let categories = self.settings.debug_categories;
        let width = self.settings.debug_line_width;
        self.lines.extend(
            scene
                .debug_lines
                .iter()
                .filter(|line| categories.intersects(line.category))
                .map(|line| LineRaw::new(line, width)),
        );
        self.line_buffer.write(
            self.gpu.device(),
            self.gpu.queue(),
            bytemuck::cast_slice(&self.lines),
        );

        let triangles = self
            .batcher
            .batches()
            .iter()
            .filter_map(|batch| {
                let mesh = self.meshes.get(batch.key.mesh)?;
                Some(u64::from(mesh.index_count / 3) * u64::from(batch.instance_count))
            })
            .sum();
        RenderStats {
            draw_calls: 0,
            triangles,
            instances: counts.visible,
            culled: counts.culled,
            batches: self.batcher.batches().len() as u32,
            debug_lines: self.lines.len() as u32,
            cpu_prepare_time: start.elapsed(),
            skipped: false,
        }
    }

    /// MSAA samples for a target format: the setting, clamped to what the adapter offers.
    fn sample_count(&mut self, format: wgpu::TextureFormat) -> u32 {
        let requested = self.settings.msaa_samples.max(1);
        let samples = self.gpu.supported_sample_count(format, requested);
        if samples != requested && !self.msaa_warned {
            tracing::warn!(
                requested,
                used = samples,
                ?format,
                "MSAA sample count not supported, using fewer"
            );
            self.msaa_warned = true;
        }
        samples
    }
}

fn shader_event(error: &crate::pipeline::ShaderError) -> GraphicsEvent {
    match error {
        crate::pipeline::ShaderError::Compile { shader, message } => {
            GraphicsEvent::ShaderCompileFailed {
                shader: shader.clone(),
                message: message.clone(),
            }
        }
        crate::pipeline::ShaderError::Read { path, source } => GraphicsEvent::ShaderCompileFailed {
            shader: path.display().to_string(),
            message: source.to_string(),
        },
    }
}
