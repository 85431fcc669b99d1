//! [`GpuTexture`]: a sampled 2D texture, all mips uploaded.

use image::RgbaImage;

use super::mipmaps;

/// A 2D texture (sRGB for colour maps, linear for data maps), all mips uploaded.
#[derive(Debug)]
pub(crate) struct GpuTexture {
    pub(crate) texture: wgpu::Texture,
    pub(crate) view: wgpu::TextureView,
}

impl GpuTexture {
    /// Uploads `levels`: level 0, then each mip level below it. `linear` stores the bytes as
    /// plain values (normal, metallic-roughness, occlusion maps) instead of sRGB colour.
    pub(crate) fn upload(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        levels: &[RgbaImage],
        label: &str,
        linear: bool,
    ) -> Self {
        let fallback = RgbaImage::from_pixel(1, 1, image::Rgba([255; 4]));
        let levels = if levels.is_empty() {
            std::slice::from_ref(&fallback)
        } else {
            levels
        };
        let (width, height) = levels[0].dimensions();
        let count = (levels.len() as u32).min(mipmaps::mip_level_count(width, height));
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
            mip_level_count: count,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: if linear {
                wgpu::TextureFormat::Rgba8Unorm
            } else {
                wgpu::TextureFormat::Rgba8UnormSrgb
            },
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        });
        for (level, img) in levels.iter().take(count as usize).enumerate() {
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
        Self { texture, view }
    }

    /// Bytes of texel data of every mip level.
    pub(crate) fn bytes(&self) -> u64 {
        let (w, h) = self.size();
        (0..self.texture.mip_level_count())
            .map(|level| u64::from((w >> level).max(1)) * u64::from((h >> level).max(1)) * 4)
            .sum()
    }

    /// Width and height of mip level 0, pixels.
    pub(crate) fn size(&self) -> (u32, u32) {
        (self.texture.width(), self.texture.height())
    }
}
