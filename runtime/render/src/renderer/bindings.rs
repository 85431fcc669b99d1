//! [`Bindings`]: the bind groups that name buffers and textures the renderer may replace —
//! the frame group (uniforms + objects), the shadow-view group (objects + view matrices) and
//! the lighting group (shadow maps + sky maps) — rebuilt when one of them is.

use crate::environment::EnvironmentMaps;
use crate::frame::ShadowViewRaw;
use crate::pipeline::Layouts;
use crate::shadow::ShadowMaps;

/// The renderer's replaceable bind groups.
#[derive(Debug)]
pub(crate) struct Bindings {
    pub(crate) frame: wgpu::BindGroup,
    pub(crate) shadow_view: wgpu::BindGroup,
    pub(crate) lighting: wgpu::BindGroup,
    shadow_sampler: wgpu::Sampler,
}

impl Bindings {
    pub(crate) fn new(
        device: &wgpu::Device,
        layouts: &Layouts,
        frame: &wgpu::Buffer,
        objects: &wgpu::Buffer,
        shadow_views: &wgpu::Buffer,
        shadow_maps: &ShadowMaps,
        environment: &EnvironmentMaps,
    ) -> Self {
        let shadow_sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("onyx shadow sampler"),
            address_mode_u: wgpu::AddressMode::ClampToEdge,
            address_mode_v: wgpu::AddressMode::ClampToEdge,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            // Lit where the stored depth is at least the fragment's (depth 0 at the light).
            compare: Some(wgpu::CompareFunction::LessEqual),
            ..Default::default()
        });
        let lighting = lighting_group(device, layouts, shadow_maps, environment, &shadow_sampler);
        Self {
            frame: frame_group(device, layouts, frame, objects),
            shadow_view: shadow_group(device, layouts, objects, shadow_views),
            lighting,
            shadow_sampler,
        }
    }

    /// After the object or shadow-view buffer was replaced.
    pub(crate) fn rebuild_buffers(
        &mut self,
        device: &wgpu::Device,
        layouts: &Layouts,
        frame: &wgpu::Buffer,
        objects: &wgpu::Buffer,
        shadow_views: &wgpu::Buffer,
    ) {
        self.frame = frame_group(device, layouts, frame, objects);
        self.shadow_view = shadow_group(device, layouts, objects, shadow_views);
    }

    /// After a shadow map or the sky's maps were replaced.
    pub(crate) fn rebuild_lighting(
        &mut self,
        device: &wgpu::Device,
        layouts: &Layouts,
        shadow_maps: &ShadowMaps,
        environment: &EnvironmentMaps,
    ) {
        self.lighting = lighting_group(
            device,
            layouts,
            shadow_maps,
            environment,
            &self.shadow_sampler,
        );
    }
}

fn frame_group(
    device: &wgpu::Device,
    layouts: &Layouts,
    frame: &wgpu::Buffer,
    objects: &wgpu::Buffer,
) -> wgpu::BindGroup {
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("onyx frame"),
        layout: &layouts.frame,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: frame.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: objects.as_entire_binding(),
            },
        ],
    })
}

fn shadow_group(
    device: &wgpu::Device,
    layouts: &Layouts,
    objects: &wgpu::Buffer,
    shadow_views: &wgpu::Buffer,
) -> wgpu::BindGroup {
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("onyx shadow view"),
        layout: &layouts.shadow_view,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 1,
                resource: objects.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: shadow_views,
                    offset: 0,
                    size: wgpu::BufferSize::new(size_of::<ShadowViewRaw>() as u64),
                }),
            },
        ],
    })
}

fn lighting_group(
    device: &wgpu::Device,
    layouts: &Layouts,
    shadow_maps: &ShadowMaps,
    environment: &EnvironmentMaps,
    shadow_sampler: &wgpu::Sampler,
) -> wgpu::BindGroup {
    let view = wgpu::BindingResource::TextureView;
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("onyx lighting"),
        layout: &layouts.lighting,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: view(&shadow_maps.directional.array_view),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: view(&shadow_maps.local.array_view),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: wgpu::BindingResource::Sampler(shadow_sampler),
            },
            wgpu::BindGroupEntry {
                binding: 3,
                resource: view(&environment.specular),
            },
            wgpu::BindGroupEntry {
                binding: 4,
                resource: view(&environment.irradiance),
            },
            wgpu::BindGroupEntry {
                binding: 5,
                resource: view(&environment.brdf),
            },
            wgpu::BindGroupEntry {
                binding: 6,
                resource: wgpu::BindingResource::Sampler(&environment.sampler),
            },
            wgpu::BindGroupEntry {
                binding: 7,
                resource: view(&environment.background),
            },
        ],
    })
}
