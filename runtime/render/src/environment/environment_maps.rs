//! [`EnvironmentMaps`]: the sky's prefiltered specular cube, irradiance cube and the BRDF
//! integration table, baked on the GPU by `environment.wgsl` from the procedural sky or from
//! an equirectangular HDR image ([`SkyImage`]), and the sky cube itself (the background of an
//! image sky).

use wgpu::util::DeviceExt;

use super::sky_image::SkyImage;
use crate::pipeline::{ShaderError, ShaderSource};
use crate::sky::Sky;

/// Side of the procedural sky cube the prefiltering reads, texels (full mip chain).
const SOURCE_SIZE: u32 = 128;
/// Side of the cube an image sky is resampled into: it is also the background, so sharper.
const IMAGE_SOURCE_SIZE: u32 = 256;
/// Side of the specular cube's level 0, texels.
const SPECULAR_SIZE: u32 = 64;
/// Mip levels of the specular cube: level `m` holds roughness `m / (SPECULAR_MIPS - 1)`.
pub(crate) const SPECULAR_MIPS: u32 = 6;
/// Side of the irradiance cube, texels (irradiance varies slowly).
const IRRADIANCE_SIZE: u32 = 16;
/// Side of the BRDF table (N·V across, roughness down), texels.
const BRDF_SIZE: u32 = 64;
/// Format of every environment texture.
const ENV_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;
/// Bytes between the uniform blocks of the bake's draws (dynamic offsets).
const UNIFORM_STRIDE: u64 = 256;

/// One bake draw's parameters (`Bake` in `environment.wgsl`).
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
struct BakeRaw {
    /// x: face, y: roughness, z: target side (texels), w: source side (texels).
    params: [f32; 4],
    zenith: [f32; 4],
    horizon: [f32; 4],
    ground: [f32; 4],
    padding: [[f32; 4]; 12],
}

/// The sky's image-based light, ready to bind.
#[derive(Debug)]
pub(crate) struct EnvironmentMaps {
    pub(crate) specular: wgpu::TextureView,
    pub(crate) irradiance: wgpu::TextureView,
    pub(crate) brdf: wgpu::TextureView,
    pub(crate) sampler: wgpu::Sampler,
    /// The sky cube the maps were filtered from (drawn as the background of an image sky).
    pub(crate) background: wgpu::TextureView,
    /// Whether they come from the sky's image (else from its procedural colours).
    pub(crate) from_image: bool,
    /// The sky they were baked from.
    pub(crate) sky: Sky,
}

impl EnvironmentMaps {
    /// Highest mip of the specular cube (roughness 1).
    pub(crate) fn max_mip() -> f32 {
        (SPECULAR_MIPS - 1) as f32
    }

    /// Bakes `sky` with `environment.wgsl` from `source` (the embedded copy if the folder's
    /// fails, which is returned as a warning). A sky image that cannot be read is logged as
    /// one warning and the procedural sky is baked instead.
    ///
    /// # Errors
    /// [`ShaderError`] when even the embedded shader does not compile.
    pub(crate) fn bake(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        source: &ShaderSource,
        sky: &Sky,
    ) -> Result<(Self, Option<ShaderError>), ShaderError> {
        let (module, warning) = match source
            .read_standalone("environment.wgsl")
            .and_then(|t| compile(device, &t))
        {
            Ok(module) => (module, None),
            Err(error) => (
                compile(
                    device,
                    &ShaderSource::read_embedded_standalone("environment.wgsl"),
                )?,
                Some(error),
            ),
        };
        let image = sky.image.as_deref().and_then(|path| {
            SkyImage::load(path, IMAGE_SOURCE_SIZE, sky.intensity)
                .inspect_err(|error| {
                    tracing::warn!("{error}; keeping the procedural sky");
                })
                .ok()
        });
        let source_size = image.as_ref().map_or(SOURCE_SIZE, |i| i.size);
        let cube = |label, size, mips| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d {
                    width: size,
                    height: size,
                    depth_or_array_layers: 6,
                },
                mip_level_count: mips,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: ENV_FORMAT,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                    | wgpu::TextureUsages::TEXTURE_BINDING
                    | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            })
        };
        let source_mips = 32 - source_size.leading_zeros();
        let sky_cube = cube("onyx sky cube", source_size, source_mips);
        if let Some(image) = &image {
            upload(queue, &sky_cube, image);
        }
        let specular = cube("onyx sky specular", SPECULAR_SIZE, SPECULAR_MIPS);
        let irradiance = cube("onyx sky irradiance", IRRADIANCE_SIZE, 1);
        let brdf = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("onyx brdf table"),
            size: wgpu::Extent3d {
                width: BRDF_SIZE,
                height: BRDF_SIZE,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: ENV_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        });
        let dummy = cube("onyx empty cube", 1, 1);
        let cube_view = |t: &wgpu::Texture| {
            t.create_view(&wgpu::TextureViewDescriptor {
                dimension: Some(wgpu::TextureViewDimension::Cube),
                ..Default::default()
            })
        };
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("onyx sky sampler"),
            address_mode_u: wgpu::AddressMode::ClampToEdge,
            address_mode_v: wgpu::AddressMode::ClampToEdge,
            address_mode_w: wgpu::AddressMode::ClampToEdge,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            mipmap_filter: wgpu::MipmapFilterMode::Linear,
            ..Default::default()
        });

        // Every draw: (target view, entry point, params, reads the sky cube).
        let face_view = |t: &wgpu::Texture, face: u32, mip: u32| {
            t.create_view(&wgpu::TextureViewDescriptor {
                dimension: Some(wgpu::TextureViewDimension::D2),
                base_array_layer: face,
                array_layer_count: Some(1),
                base_mip_level: mip,
                mip_level_count: Some(1),
                ..Default::default()
            })
        };
        let mut draws: Vec<(wgpu::TextureView, &'static str, [f32; 4], bool)> = Vec::new();
        let procedural_mips = if image.is_some() { 0 } else { source_mips };
        for mip in 0..procedural_mips {
            let size = (SOURCE_SIZE >> mip).max(1) as f32;
            for face in 0..6 {
                draws.push((
                    face_view(&sky_cube, face, mip),
                    "fs_sky",
                    [face as f32, 0.0, size, 0.0],
                    false,
                ));
            }
        }
        for mip in 0..SPECULAR_MIPS {
            let size = (SPECULAR_SIZE >> mip).max(1) as f32;
            let roughness = mip as f32 / (SPECULAR_MIPS - 1) as f32;
            // Level 0 is the sky itself: drawn from its function, or read from the image's cube.
            let filtered = mip > 0 || image.is_some();
            for face in 0..6 {
                let entry = if filtered { "fs_specular" } else { "fs_sky" };
                draws.push((
                    face_view(&specular, face, mip),
                    entry,
                    [face as f32, roughness, size, source_size as f32],
                    filtered,
                ));
            }
        }
        for face in 0..6 {
            draws.push((
                face_view(&irradiance, face, 0),
                "fs_irradiance",
                [face as f32, 1.0, IRRADIANCE_SIZE as f32, source_size as f32],
                true,
            ));
        }
        draws.push((
            brdf.create_view(&wgpu::TextureViewDescriptor::default()),
            "fs_brdf",
            [0.0, 0.0, BRDF_SIZE as f32, 0.0],
            false,
        ));

        let colors = |c: glam::Vec3| (c * sky.intensity).extend(0.0).to_array();
        let blocks: Vec<BakeRaw> = draws
            .iter()
            .map(|(_, _, params, _)| BakeRaw {
                params: *params,
                zenith: colors(sky.zenith),
                horizon: colors(sky.horizon),
                ground: colors(sky.ground),
                padding: [[0.0; 4]; 12],
            })
            .collect();
        let uniforms = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("onyx sky bake"),
            contents: bytemuck::cast_slice(&blocks),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("onyx sky bake"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: true,
                        min_binding_size: wgpu::BufferSize::new(size_of::<BakeRaw>() as u64),
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: true },
                        view_dimension: wgpu::TextureViewDimension::Cube,
                        multisampled: false,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 2,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                    count: None,
                },
            ],
        });
        let group = |cube: &wgpu::TextureView| {
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("onyx sky bake"),
                layout: &layout,
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                            buffer: &uniforms,
                            offset: 0,
                            size: wgpu::BufferSize::new(size_of::<BakeRaw>() as u64),
                        }),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: wgpu::BindingResource::TextureView(cube),
                    },
                    wgpu::BindGroupEntry {
                        binding: 2,
                        resource: wgpu::BindingResource::Sampler(&sampler),
                    },
                ],
            })
        };
        let reads_sky = group(&cube_view(&sky_cube));
        let reads_nothing = group(&cube_view(&dummy));
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("onyx sky bake"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let mut pipelines = std::collections::HashMap::new();
        for entry in ["fs_sky", "fs_specular", "fs_irradiance", "fs_brdf"] {
            let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(entry),
                layout: Some(&pipeline_layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs_main"),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    buffers: &[],
                },
                primitive: wgpu::PrimitiveState::default(),
                depth_stencil: None,
                multisample: wgpu::MultisampleState::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some(entry),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: ENV_FORMAT,
                        blend: None,
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            });
            pipelines.insert(entry, pipeline);
        }
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("onyx sky bake"),
        });
        for (i, (view, entry, _, reads)) in draws.iter().enumerate() {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("onyx sky bake"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view,
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
            if let Some(pipeline) = pipelines.get(entry) {
                pass.set_pipeline(pipeline);
            }
            let offset = (i as u64 * UNIFORM_STRIDE) as u32;
            pass.set_bind_group(
                0,
                if *reads { &reads_sky } else { &reads_nothing },
                &[offset],
            );
            pass.draw(0..3, 0..1);
        }
        queue.submit([encoder.finish()]);
        let maps = Self {
            specular: cube_view(&specular),
            irradiance: cube_view(&irradiance),
            brdf: brdf.create_view(&wgpu::TextureViewDescriptor::default()),
            sampler,
            background: cube_view(&sky_cube),
            from_image: image.is_some(),
            sky: sky.clone(),
        };
        Ok((maps, warning))
    }
}

/// Writes every level of every face of `image` into `cube`.
fn upload(queue: &wgpu::Queue, cube: &wgpu::Texture, image: &SkyImage) {
    for (mip, faces) in image.levels.iter().enumerate() {
        let side = (image.size >> mip).max(1);
        for (face, texels) in faces.iter().enumerate() {
            queue.write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: cube,
                    mip_level: mip as u32,
                    origin: wgpu::Origin3d {
                        x: 0,
                        y: 0,
                        z: face as u32,
                    },
                    aspect: wgpu::TextureAspect::All,
                },
                bytemuck::cast_slice(texels),
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(side * 8),
                    rows_per_image: Some(side),
                },
                wgpu::Extent3d {
                    width: side,
                    height: side,
                    depth_or_array_layers: 1,
                },
            );
        }
    }
}

fn compile(device: &wgpu::Device, text: &str) -> Result<wgpu::ShaderModule, ShaderError> {
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("environment.wgsl"),
        source: wgpu::ShaderSource::Wgsl(text.into()),
    });
    match pollster::block_on(scope.pop()) {
        None => Ok(module),
        Some(error) => Err(ShaderError::Compile {
            shader: "environment.wgsl".to_owned(),
            message: error.to_string(),
        }),
    }
}
