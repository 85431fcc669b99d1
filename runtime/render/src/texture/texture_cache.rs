//! [`TextureCache`]: every texture uploaded to a renderer, textures loaded by source, the
//! sources that failed (reported once), and the two built-ins: plain white and the magenta
//! "missing texture" checker.

use std::collections::{HashMap, HashSet};

use image::RgbaImage;

use super::gpu_texture::GpuTexture;
use super::texture_handle::TextureHandle;
use super::texture_source::TextureSource;
use crate::model_material::ImageSource;

/// Side of the fallback checker texture, pixels.
const CHECKER_SIZE: u32 = 64;
/// Side of one checker cell, pixels.
const CHECKER_CELL: u32 = 8;
/// Magenta of the "missing texture" checker (sRGB).
const CHECKER_MAGENTA: [u8; 4] = [255, 0, 255, 255];
/// The other checker colour (sRGB).
const CHECKER_DARK: [u8; 4] = [20, 20, 20, 255];

/// Uploaded textures and the source → handle cache.
#[derive(Debug)]
pub(crate) struct TextureCache {
    sampler: wgpu::Sampler,
    textures: Vec<GpuTexture>,
    by_source: HashMap<ImageSource, TextureHandle>,
    failed: HashSet<ImageSource>,
    white: TextureHandle,
    checker: TextureHandle,
    /// Bytes of every uploaded level, for the GPU memory figures.
    bytes: u64,
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
            by_source: HashMap::new(),
            failed: HashSet::new(),
            white: TextureHandle(0),
            checker: TextureHandle(0),
            bytes: 0,
        };
        let white = RgbaImage::from_pixel(1, 1, image::Rgba([255; 4]));
        cache.white = cache.add(device, queue, layout, &[white], "onyx white");
        let checker = TextureSource::from_image(checker_image(), true);
        cache.checker = cache.add(
            device,
            queue,
            layout,
            &checker.levels,
            "onyx missing-texture checker",
        );
        cache
    }

    /// Uploads an image and its mip levels.
    pub(crate) fn add(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        layout: &wgpu::BindGroupLayout,
        levels: &[RgbaImage],
        label: &str,
    ) -> TextureHandle {
        let handle = TextureHandle(self.textures.len() as u32);
        self.bytes += levels
            .iter()
            .map(|l| u64::from(l.width()) * u64::from(l.height()) * 4)
            .sum::<u64>();
        self.textures.push(GpuTexture::upload(
            device,
            queue,
            layout,
            &self.sampler,
            levels,
            label,
        ));
        handle
    }

    /// The texture of `source`, if it was uploaded.
    pub(crate) fn cached(&self, source: &ImageSource) -> Option<TextureHandle> {
        self.by_source.get(&canonical(source)).copied()
    }

    /// Uploads a decoded image for `source` (once: a second call returns the first handle).
    pub(crate) fn insert(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        layout: &wgpu::BindGroupLayout,
        source: &ImageSource,
        texture: &TextureSource,
    ) -> TextureHandle {
        let key = canonical(source);
        if let Some(&handle) = self.by_source.get(&key) {
            return handle;
        }
        let handle = self.add(device, queue, layout, &texture.levels, &source.to_string());
        let (width, height) = texture.original_size;
        tracing::debug!(%source, width, height, "texture uploaded");
        self.by_source.insert(key, handle);
        handle
    }

    /// Records that `source` failed; `true` the first time (report it then, only then).
    pub(crate) fn mark_failed(&mut self, source: &ImageSource) -> bool {
        self.failed.insert(canonical(source))
    }

    /// Whether `source` failed before.
    pub(crate) fn has_failed(&self, source: &ImageSource) -> bool {
        self.failed.contains(&canonical(source))
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

    /// Bytes of texel data uploaded, every mip level counted.
    pub(crate) fn bytes(&self) -> u64 {
        self.bytes
    }
}

/// The key a source is cached under: a file by its canonical path when it exists.
fn canonical(source: &ImageSource) -> ImageSource {
    match source {
        ImageSource::File(path) => ImageSource::File(crate::mesh::cache_key(path)),
        ImageSource::Embedded { model, index } => ImageSource::Embedded {
            model: crate::mesh::cache_key(model),
            index: *index,
        },
    }
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
