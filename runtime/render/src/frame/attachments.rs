//! [`Attachments`]: the depth buffer and (when MSAA is on) the multisampled colour buffer
//! that go with a target of a given size.

/// Depth and MSAA textures for one target size / sample count.
#[derive(Debug)]
pub(crate) struct Attachments {
    pub(crate) size: (u32, u32),
    pub(crate) samples: u32,
    pub(crate) format: wgpu::TextureFormat,
    pub(crate) depth: wgpu::TextureView,
    /// Multisampled colour buffer, resolved into the target; `None` when `samples == 1`.
    pub(crate) msaa: Option<wgpu::TextureView>,
}

impl Attachments {
    /// Reuses `slot` when it matches, else recreates it.
    pub(crate) fn ensure<'a>(
        slot: &'a mut Option<Attachments>,
        device: &wgpu::Device,
        size: (u32, u32),
        format: wgpu::TextureFormat,
        samples: u32,
    ) -> &'a Attachments {
        let stale = slot
            .as_ref()
            .is_none_or(|a| a.size != size || a.samples != samples || a.format != format);
        if stale {
            *slot = Some(Self::new(device, size, format, samples));
        }
        slot.get_or_insert_with(|| Self::new(device, size, format, samples))
    }

    fn new(
        device: &wgpu::Device,
        size: (u32, u32),
        format: wgpu::TextureFormat,
        samples: u32,
    ) -> Self {
        let extent = wgpu::Extent3d {
            width: size.0.max(1),
            height: size.1.max(1),
            depth_or_array_layers: 1,
        };
        let depth = device
            .create_texture(&wgpu::TextureDescriptor {
                label: Some("onyx depth"),
                size: extent,
                mip_level_count: 1,
                sample_count: samples,
                dimension: wgpu::TextureDimension::D2,
                format: crate::DEPTH_FORMAT,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                view_formats: &[],
            })
            .create_view(&wgpu::TextureViewDescriptor::default());
        let msaa = (samples > 1).then(|| {
            device
                .create_texture(&wgpu::TextureDescriptor {
                    label: Some("onyx msaa colour"),
                    size: extent,
                    mip_level_count: 1,
                    sample_count: samples,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                    view_formats: &[],
                })
                .create_view(&wgpu::TextureViewDescriptor::default())
        });
        Self {
            size,
            samples,
            format,
            depth,
            msaa,
        }
    }
}
