//! [`ShadowMaps`]: the two depth arrays shadows are drawn into — the directional cascades and
//! the local (spot, point-face) layers — sized to what the frame needs (1×1 when unused, so
//! the lighting bind group always has something to bind).

/// Depth format of shadow maps.
pub(crate) const SHADOW_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// One depth array and a view per layer.
#[derive(Debug)]
pub(crate) struct DepthArray {
    pub(crate) size: u32,
    pub(crate) layers: u32,
    /// All layers, for sampling.
    pub(crate) array_view: wgpu::TextureView,
    /// One view per layer, for drawing.
    pub(crate) layer_views: Vec<wgpu::TextureView>,
}

impl DepthArray {
    fn new(device: &wgpu::Device, size: u32, layers: u32, label: &str) -> Self {
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d {
                width: size,
                height: size,
                depth_or_array_layers: layers,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: SHADOW_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        });
        let array_view = texture.create_view(&wgpu::TextureViewDescriptor {
            label: Some(label),
            dimension: Some(wgpu::TextureViewDimension::D2Array),
            ..Default::default()
        });
        let layer_views = (0..layers)
            .map(|layer| {
                texture.create_view(&wgpu::TextureViewDescriptor {
                    label: Some(label),
                    dimension: Some(wgpu::TextureViewDimension::D2),
                    base_array_layer: layer,
                    array_layer_count: Some(1),
                    ..Default::default()
                })
            })
            .collect();
        Self {
            size,
            layers,
            array_view,
            layer_views,
        }
    }
}

/// The directional and local shadow arrays.
#[derive(Debug)]
pub(crate) struct ShadowMaps {
    pub(crate) directional: DepthArray,
    pub(crate) local: DepthArray,
}

impl ShadowMaps {
    pub(crate) fn new(device: &wgpu::Device) -> Self {
        Self {
            directional: DepthArray::new(device, 1, 1, "onyx directional shadows"),
            local: DepthArray::new(device, 1, 1, "onyx local shadows"),
        }
    }

    /// Makes both arrays big enough: `cascades` layers of `dir_size` and `local_layers` of
    /// `local_size` (none used: 1×1). Returns whether a texture was replaced (the bind groups
    /// that sample them must be rebuilt).
    pub(crate) fn ensure(
        &mut self,
        device: &wgpu::Device,
        dir_size: u32,
        cascades: u32,
        local_size: u32,
        local_layers: u32,
    ) -> bool {
        let max = device.limits().max_texture_dimension_2d;
        let (dir_size, cascades) = if cascades == 0 {
            (1, 1)
        } else {
            (dir_size.clamp(1, max), cascades)
        };
        let (local_size, local_layers) = if local_layers == 0 {
            (1, 1)
        } else {
            (local_size.clamp(1, max), local_layers)
        };
        let mut changed = false;
        if self.directional.size != dir_size || self.directional.layers != cascades {
            self.directional =
                DepthArray::new(device, dir_size, cascades, "onyx directional shadows");
            changed = true;
        }
        // Within one size the local array only grows, so lights turning on and off do not
        // reallocate it every frame.
        if self.local.size != local_size || self.local.layers < local_layers {
            let layers = if self.local.size == local_size {
                local_layers.max(self.local.layers)
            } else {
                local_layers
            };
            self.local = DepthArray::new(device, local_size, layers, "onyx local shadows");
            changed = true;
        }
        changed
    }
}
