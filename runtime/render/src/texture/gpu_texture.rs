//! [`GpuTexture`]: a sampled texture with its bind group.

use image::RgbaImage;

use super::mipmaps;

/// A 2D sRGB texture, all mips uploaded, bound with the shared sampler.
#[derive(Debug)]
pub(crate) struct GpuTexture {
    pub(crate) texture: wgpu::Texture,
    pub(crate) bind_group: wgpu::BindGroup,
}

impl GpuTexture {
    /// Uploads `levels` (sRGB): level 0, then each mip level below it.
    pub(crate) fn upload(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        layout: &wgpu::BindGroupLayout,
        sampler: &wgpu::Sampler,
        levels: &[RgbaImage],
        label: &str,
    ) -> Self {
        let fallback = RgbaImage::from_pixel(1, 1, image::Rgba([255; 4]));
        let levels = if levels.is_empty() {
            std::slice::from_ref(&fallback)
        } else {
            levels
        };
        let (width, height) = levels[0].dimensions();
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
            mip_level_count: (levels.len() as u32).min(mipmaps::mip_level_count(width, height)),
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba8UnormSrgb,
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        });
        let count = (levels.len() as u32).min(mipmaps::mip_level_count(width, height)) as usize;
        for (level, img) in levels.iter().take(count).enumerate() {
            let (w, h) = img.dimensions();
            queue.write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &texture,
                    mip_level: level as u32,
                    origin: wgpu::Origin3d::ZERO,
                    aspect: wgpu::TextureAspect::All,
                },
                img.as_raw(),
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(4 * w),
                    rows_per_image: Some(h),
                },
                wgpu::Extent3d {
                    width: w,
                    height: h,
                    depth_or_array_layers: 1,
                },
            );
        }
        let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(label),
            layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(sampler),
                },
            ],
        });
        Self {
            texture,
            bind_group,
        }
    }

    /// Width and height of mip level 0, pixels.
    pub(crate) fn size(&self) -> (u32, u32) {
        (self.texture.width(), self.texture.height())
    }
}
