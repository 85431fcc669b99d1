//! [`TextureCache`]: every texture uploaded to a renderer, textures loaded by path, and the
//! two built-ins: plain white and the magenta "missing texture" checker.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use image::RgbaImage;

use super::gpu_texture::GpuTexture;
use super::texture_handle::TextureHandle;
use super::texture_load_error::TextureLoadError;

/// Side of the fallback checker texture, pixels.
const CHECKER_SIZE: u32 = 64;
/// Side of one checker cell, pixels.
const CHECKER_CELL: u32 = 8;
/// Magenta of the "missing texture" checker (sRGB).
const CHECKER_MAGENTA: [u8; 4] = [255, 0, 255, 255];
/// The other checker colour (sRGB).
const CHECKER_DARK: [u8; 4] = [20, 20, 20, 255];

/// Uploaded textures and the path → handle cache.
#[derive(Debug)]
pub(crate) struct TextureCache {
    sampler: wgpu::Sampler,
    textures: Vec<GpuTexture>,
    by_path: HashMap<PathBuf, TextureHandle>,
    white: TextureHandle,
    checker: TextureHandle,
}

impl TextureCache {
    pub(crate) fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        layout: &wgpu::BindGroupLayout,
    ) -> Self {
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("onyx albedo sampler"),
            address_mode_u: wgpu::AddressMode::Repeat,
            address_mode_v: wgpu::AddressMode::Repeat,
            address_mode_w: wgpu::AddressMode::Repeat,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            mipmap_filter: wgpu::MipmapFilterMode::Linear,
            ..Default::default()
        });
        let mut cache = Self {
            sampler,
            textures: Vec::new(),
            by_path: HashMap::new(),
            white: TextureHandle(0),
            checker: TextureHandle(0),
        };
        let white = RgbaImage::from_pixel(1, 1, image::Rgba([255; 4]));
        cache.white = cache.add(device, queue, layout, &white, false, "onyx white");
        cache.checker = cache.add(
            device,
            queue,
            layout,
            &checker_image(),
            false,
            "onyx missing-texture checker",
        );
        cache
    }

    /// Uploads an image.
    pub(crate) fn add(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        layout: &wgpu::BindGroupLayout,
        image: &RgbaImage,
        mips: bool,
        label: &str,
    ) -> TextureHandle {
        let handle = TextureHandle(self.textures.len() as u32);
        self.textures.push(GpuTexture::upload(
            device,
            queue,
            layout,
            &self.sampler,
            image,
            mips,
            label,
        ));
        handle
    }

    /// Loads an image file once; later calls with the same file return the same handle.
    pub(crate) fn load(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        layout: &wgpu::BindGroupLayout,
        path: &Path,
    ) -> Result<TextureHandle, TextureLoadError> {
        let key = crate::mesh::cache_key(path);
        if let Some(&handle) = self.by_path.get(&key) {
            return Ok(handle);
        }
        let image = decode(path)?;
        let max = device.limits().max_texture_dimension_2d;
        let (width, height) = image.dimensions();
        if width > max || height > max {
            return Err(TextureLoadError::TooLarge {
                path: path.to_owned(),
                width,
                height,
                max,
            });
        }
        let handle = self.add(
            device,
            queue,
            layout,
            &image,
            true,
            &path.display().to_string(),
        );
        tracing::debug!(path = %path.display(), width, height, "texture loaded");
        self.by_path.insert(key, handle);
        Ok(handle)
    }

    pub(crate) fn get(&self, handle: TextureHandle) -> Option<&GpuTexture> {
        self.textures.get(handle.0 as usize)
    }

    /// Plain white 1×1 (the texture of untextured materials).
    pub(crate) fn white(&self) -> TextureHandle {
        self.white
    }

    /// Magenta/black checker shown in place of a texture that failed to load.
    pub(crate) fn checker(&self) -> TextureHandle {
        self.checker
    }
}

/// Reads and decodes a PNG or JPEG file (format from its content).
fn decode(path: &Path) -> Result<RgbaImage, TextureLoadError> {
    let bytes = std::fs::read(path).map_err(|source| TextureLoadError::Read {
        path: path.to_owned(),
        source,
    })?;
    let image = image::load_from_memory(&bytes).map_err(|source| TextureLoadError::Decode {
        path: path.to_owned(),
        source,
    })?;
    Ok(image.to_rgba8())
}

fn checker_image() -> RgbaImage {
    RgbaImage::from_fn(CHECKER_SIZE, CHECKER_SIZE, |x, y| {
        if (x / CHECKER_CELL + y / CHECKER_CELL).is_multiple_of(2) {
            image::Rgba(CHECKER_MAGENTA)
        } else {
            image::Rgba(CHECKER_DARK)
        }
    })
}
