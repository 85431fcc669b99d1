//! [`Renderer`]: the one entry point: owns the device, assets and pipelines, and draws a
//! [`RenderScene`] into a [`RenderTarget`].
//!
//! `render` runs named stages: `prepare` (shadow views, uniforms, culling and batching for
//! every view, uploads; timed) → acquire the target frame → `encode_shadows` (one depth pass
//! per shadow view) → `encode_scene` (the HDR pass: opaque, sky, grid, blended back to front,
//! debug lines) → `encode_tonemap` (exposure, tone mapping, sRGB into the target) → overlay →
//! submit → present. Each stage has its file in `renderer/`; asset loading is in
//! `renderer/assets.rs`, the bind groups that change with buffers and maps in
//! `renderer/bindings.rs`.

mod assets;
mod bindings;
mod encode;
mod prepare;
mod shadow_pass;
mod tonemap_pass;

use crate::builtin_meshes::{BuiltinMeshes, BUILTIN_RINGS, BUILTIN_SEGMENTS};
use crate::environment::EnvironmentMaps;
use crate::frame::{Batcher, FrameUniforms, GrowableBuffer, LineRaw};
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
use crate::shadow::{ShadowAnchor, ShadowMaps, ShadowPlan};
use crate::texture::TextureCache;

use bindings::Bindings;

/// Smallest staging chunk of the per-frame uploads (larger writes get a chunk of their size,
/// reused the next frame).
const STAGING_CHUNK: u64 = 1 << 20;

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
    /// Every object some view sees (storage).
    object_buffer: GrowableBuffer,
    /// Object slots per instance, for every view's batches (vertex, per instance).
    index_buffer: GrowableBuffer,
    /// One view-projection per shadow pass (uniform, dynamic offsets).
    shadow_view_buffer: GrowableBuffer,
    line_buffer: GrowableBuffer,
    /// Staging memory of the uploads above, reused frame after frame.
    belt: wgpu::util::StagingBelt,
    shadow_maps: ShadowMaps,
    environment: EnvironmentMaps,
    bindings: Bindings,
    batcher: Batcher,
    shadow_plan: ShadowPlan,
    /// Where the cascades' texel grid is laid from (kept between frames).
    shadow_anchor: ShadowAnchor,
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
        let (pipelines, warnings) = PipelineLibrary::new(&device, source.clone())?;
        for warning in warnings {
            gpu.events().push(shader_event(&warning));
        }
        let (environment, warning) =
            EnvironmentMaps::bake(&device, gpu.queue(), &source, &settings.sky)?;
        if let Some(warning) = warning {
            gpu.events().push(shader_event(&warning));
        }
        let textures = TextureCache::new(&device, gpu.queue());
        let frame_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("onyx frame uniforms"),
            size: size_of::<FrameUniforms>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
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
        let object_buffer =
            GrowableBuffer::new(&device, wgpu::BufferUsages::STORAGE, "onyx objects");
        let index_buffer =
            GrowableBuffer::new(&device, wgpu::BufferUsages::VERTEX, "onyx instances");
        let shadow_view_buffer =
            GrowableBuffer::new(&device, wgpu::BufferUsages::UNIFORM, "onyx shadow views");
        let line_buffer =
            GrowableBuffer::new(&device, wgpu::BufferUsages::VERTEX, "onyx debug lines");
        let shadow_maps = ShadowMaps::new(&device);
        let bindings = Bindings::new(
            &device,
            pipelines.layouts(),
            &frame_buffer,
            object_buffer.buffer(),
            shadow_view_buffer.buffer(),
            &shadow_maps,
            &environment,
        );
        tracing::info!(msaa = settings.msaa_samples, shader_dir = ?settings.shader_dir, "renderer ready");
        Ok(Self {
            gpu,
            settings,
            pipelines,
            textures,
            meshes,
            builtin,
            frame_buffer,
            object_buffer,
            index_buffer,
            shadow_view_buffer,
            line_buffer,
            belt: wgpu::util::StagingBelt::new(device.clone(), STAGING_CHUNK),
            shadow_maps,
            environment,
            bindings,
            batcher: Batcher::default(),
            shadow_plan: ShadowPlan::default(),
            shadow_anchor: ShadowAnchor::default(),
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

    /// Replaces the settings. A changed `shader_dir` reloads the shaders from it; a changed
    /// `sky` bakes its image-based light again.
    ///
    /// # Errors
    /// [`ShaderReloadError`] when the shader folder changed and some shaders failed there.
    pub fn set_settings(&mut self, settings: RenderSettings) -> Result<(), ShaderReloadError> {
        let dir_changed = settings.shader_dir != self.settings.shader_dir;
        let sky_changed = settings.sky != self.environment.sky;
        self.settings = settings;
        self.msaa_warned = false;
        if sky_changed {
            self.rebake_sky();
        }
        if dir_changed {
            let source = self.shader_source();
            self.pipelines.set_source(source);
            return self.reload_shaders();
        }
        Ok(())
    }

    fn shader_source(&self) -> ShaderSource {
        self.settings
            .shader_dir
            .clone()
            .map_or_else(ShaderSource::embedded, ShaderSource::from_dir)
    }

    /// Bakes the sky's maps again (new sky, or its shader reloaded).
    fn rebake_sky(&mut self) {
        let source = self.shader_source();
        match EnvironmentMaps::bake(
            self.gpu.device(),
            self.gpu.queue(),
            &source,
            &self.settings.sky,
        ) {
            Ok((environment, warning)) => {
                if let Some(warning) = warning {
                    self.gpu.events().push(shader_event(&warning));
                }
                self.environment = environment;
                self.bindings.rebuild_lighting(
                    self.gpu.device(),
                    self.pipelines.layouts(),
                    &self.shadow_maps,
                    &self.environment,
                );
            }
            Err(error) => self.gpu.events().push(shader_event(&error)),
        }
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
        let samples = self.sample_count();
        let mut encoder =
            self.gpu
                .device()
                .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                    label: Some("onyx frame"),
                });
        let mut stats = self.prepare(scene, size, !target.format().is_srgb(), &mut encoder);
        let Some(frame) = target.begin_frame(&self.gpu, samples)? else {
            // The uploads are still submitted, so the staging belt gets its chunks back.
            self.belt.finish_and_recall_on_submit(&encoder);
            self.gpu.queue().submit([encoder.finish()]);
            self.stats = RenderStats {
                skipped: true,
                ..stats
            };
            return Ok(self.stats);
        };
        stats.shadow_draw_calls = self.encode_shadows(&mut encoder);
        stats.draw_calls = self.encode_scene(&mut encoder, &frame, scene.grid);
        self.encode_tonemap(&mut encoder, &frame);
        overlay(&mut crate::Overlay {
            device: self.gpu.device(),
            queue: self.gpu.queue(),
            encoder: &mut encoder,
            view: &frame.overlay,
            format: frame.overlay_format,
            size,
        });
        self.belt.finish_and_recall_on_submit(&encoder);
        self.gpu.queue().submit([encoder.finish()]);
        target.end_frame(&self.gpu, frame);
        self.stats = stats;
        Ok(stats)
    }

    /// MSAA samples of the HDR scene: the setting, clamped to what the adapter offers.
    fn sample_count(&mut self) -> u32 {
        let format = crate::frame::HDR_FORMAT;
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
