//! [`Attachments`]: what a target of a given size draws its scene into before tone mapping:
//! the HDR colour buffer (multisampled when MSAA is on, then resolved), and the depth buffer.

/// Format of the HDR scene colour.
pub(crate) const HDR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

/// HDR colour, its resolve target and depth for one target size / sample count.
#[derive(Debug)]
pub(crate) struct Attachments {
    pub(crate) size: (u32, u32),
    pub(crate) samples: u32,
    pub(crate) depth: wgpu::TextureView,
    /// The HDR colour the scene is drawn into (multisampled when `samples > 1`).
    pub(crate) hdr: wgpu::TextureView,
    /// Single-sampled HDR colour the multisampled one resolves into; `None` when
    /// `samples == 1` (then `hdr` itself is read by tone mapping).
    pub(crate) resolve: Option<wgpu::TextureView>,
}

impl Attachments {
    /// Reuses `slot` when it matches, else recreates it.
    pub(crate) fn ensure<'a>(
        slot: &'a mut Option<Attachments>,
        device: &wgpu::Device,
        size: (u32, u32),
        samples: u32,
    ) -> &'a Attachments {
        let stale = slot
            .as_ref()
            .is_none_or(|a| a.size != size || a.samples != samples);
        if stale {
            *slot = Some(Self::new(device, size, samples));
        }
        slot.get_or_insert_with(|| Self::new(device, size, samples))
    }

    fn new(device: &wgpu::Device, size: (u32, u32), samples: u32) -> Self {
        let extent = wgpu::Extent3d {
            width: size.0.max(1),
            height: size.1.max(1),
            depth_or_array_layers: 1,
        };
        let texture = |label, format, samples, usage| {
            device
                .create_texture(&wgpu::TextureDescriptor {
                    label: Some(label),
                    size: extent,
                    mip_level_count: 1,
                    sample_count: samples,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage,
                    view_formats: &[],
                })
                .create_view(&wgpu::TextureViewDescriptor::default())
        };
        let attach = wgpu::TextureUsages::RENDER_ATTACHMENT;
        let sampled = attach | wgpu::TextureUsages::TEXTURE_BINDING;
        let depth = texture("onyx depth", crate::DEPTH_FORMAT, samples, attach);
        let (hdr, resolve) = if samples > 1 {
            (
                texture("onyx hdr msaa", HDR_FORMAT, samples, attach),
                Some(texture("onyx hdr", HDR_FORMAT, 1, sampled)),
            )
        } else {
            (texture("onyx hdr", HDR_FORMAT, 1, sampled), None)
        };
        Self {
            size,
            samples,
            depth,
            hdr,
            resolve,
        }
    }
}
