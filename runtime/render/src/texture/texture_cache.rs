//! [`TextureCache`]: every texture uploaded to a renderer, textures loaded by source and
//! colour space, the sources that failed (reported once), the built-ins (plain white, a flat
//! normal, the magenta "missing texture" checker) and the bind groups of material map sets.

use std::collections::{HashMap, HashSet};

use image::RgbaImage;

use super::gpu_texture::GpuTexture;
use super::texture_handle::TextureHandle;
use super::texture_source::TextureSource;
use crate::frame::MaterialMaps;
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
    /// By source and colour space (`true`: linear).
    by_source: HashMap<(ImageSource, bool), TextureHandle>,
    failed: HashSet<ImageSource>,
    white: TextureHandle,
    flat_normal: TextureHandle,
    checker: TextureHandle,
    /// Material bind groups by their (resolved) maps.
    material_groups: HashMap<[TextureHandle; 5], wgpu::BindGroup>,
    /// Bytes of every uploaded level, for the GPU memory figures.
    bytes: u64,
}

impl TextureCache {
    pub(crate) fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> Self {
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("onyx albedo sampler"),
            address_mode_u: wgpu::AddressMode::Repeat,
            address_mode_v: wgpu::AddressMode::Repeat,
            address_mode_w: wgpu::AddressMode::Repeat,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            mipmap_filter: wgpu::MipmapFilterMode::Linear,
            anisotropy_clamp: 16,
            ..Default::default()
        });
        let mut cache = Self {
            sampler,
            textures: Vec::new(),
            by_source: HashMap::new(),
            failed: HashSet::new(),
            white: TextureHandle(0),
            flat_normal: TextureHandle(0),
            checker: TextureHandle(0),
            material_groups: HashMap::new(),
            bytes: 0,
        };
        let white = RgbaImage::from_pixel(1, 1, image::Rgba([255; 4]));
        cache.white = cache.add(device, queue, &[white], "onyx white", false);
        let flat = RgbaImage::from_pixel(1, 1, image::Rgba([128, 128, 255, 255]));
        cache.flat_normal = cache.add(device, queue, &[flat], "onyx flat normal", true);
        let checker = TextureSource::from_image(checker_image(), true);
        cache.checker = cache.add(
            device,
            queue,
            &checker.levels,
            "onyx missing-texture checker",
            false,
        );
        cache
    }

    /// Uploads an image and its mip levels (`linear`: data, not sRGB colour).
    pub(crate) fn add(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        levels: &[RgbaImage],
        label: &str,
        linear: bool,
    ) -> TextureHandle {
        let handle = TextureHandle(self.textures.len() as u32);
        self.bytes += levels
            .iter()
            .map(|l| u64::from(l.width()) * u64::from(l.height()) * 4)
            .sum::<u64>();
        self.textures
            .push(GpuTexture::upload(device, queue, levels, label, linear));
        handle
    }

    /// The texture of `source` in that colour space, if it was uploaded.
    pub(crate) fn cached(&self, source: &ImageSource, linear: bool) -> Option<TextureHandle> {
        self.by_source.get(&(canonical(source), linear)).copied()
    }

    /// Uploads a decoded image for `source` (once per colour space: a second call returns the
    /// first handle).
    pub(crate) fn insert(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        source: &ImageSource,
        texture: &TextureSource,
        linear: bool,
    ) -> TextureHandle {
        let key = (canonical(source), linear);
        if let Some(&handle) = self.by_source.get(&key) {
            return handle;
        }
        let handle = self.add(device, queue, &texture.levels, &source.to_string(), linear);
        let (width, height) = texture.original_size;
        tracing::debug!(%source, width, height, "texture uploaded");
        self.by_source.insert(key, handle);
        handle
    }

    /// Uploads `texture` in place of the texture `handle` names (its file changed): every
    /// material using the handle shows the new image from the next frame.
    pub(crate) fn replace(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        handle: TextureHandle,
        texture: &TextureSource,
        linear: bool,
    ) {
        let Some(slot) = self.textures.get_mut(handle.0 as usize) else {
            return;
        };
        let label = format!("reloaded texture {}", handle.0);
        let old = std::mem::replace(
            slot,
            GpuTexture::upload(device, queue, &texture.levels, &label, linear),
        );
        self.bytes -= old.bytes().min(self.bytes);
        self.bytes += texture
            .levels
            .iter()
            .map(|l| u64::from(l.width()) * u64::from(l.height()) * 4)
            .sum::<u64>();
        // Bind groups hold the old view.
        self.material_groups.clear();
    }

    /// Forgets which texture `source` was uploaded as (both colour spaces) and that it
    /// failed: the next upload of it makes a new texture (its file changed).
    pub(crate) fn forget(&mut self, source: &ImageSource) {
        let key = canonical(source);
        self.by_source.retain(|(s, _), _| *s != key);
        self.failed.remove(&key);
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

    /// The bind group of a material's maps (group 1 of the mesh pipelines), built on first
    /// use; absent maps bind their neutral texture (white; a flat normal).
    pub(crate) fn material_group(
        &mut self,
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        maps: &MaterialMaps,
    ) -> &wgpu::BindGroup {
        let key = self.resolve_maps(maps);
        let textures = &self.textures;
        let sampler = &self.sampler;
        self.material_groups.entry(key).or_insert_with(|| {
            let entries: Vec<wgpu::BindGroupEntry<'_>> = key
                .iter()
                .enumerate()
                .map(|(i, h)| wgpu::BindGroupEntry {
                    binding: i as u32,
                    resource: wgpu::BindingResource::TextureView(&textures[h.0 as usize].view),
                })
                .chain(std::iter::once(wgpu::BindGroupEntry {
                    binding: 5,
                    resource: wgpu::BindingResource::Sampler(sampler),
                }))
                .collect();
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("onyx material maps"),
                layout,
                entries: &entries,
            })
        })
    }

    /// The bind group of `maps` if [`TextureCache::material_group`] built it.
    pub(crate) fn cached_material_group(&self, maps: &MaterialMaps) -> Option<&wgpu::BindGroup> {
        self.material_groups.get(&self.resolve_maps(maps))
    }

    /// The textures bound for `maps`: each map, or its slot's neutral texture.
    fn resolve_maps(&self, maps: &MaterialMaps) -> [TextureHandle; 5] {
        let resolve = |h: Option<TextureHandle>, neutral| {
            h.filter(|h| (h.0 as usize) < self.textures.len())
                .unwrap_or(neutral)
        };
        [
            resolve(maps.base_color, self.white),
            resolve(maps.metallic_roughness, self.white),
            resolve(maps.normal, self.flat_normal),
            resolve(maps.occlusion, self.white),
            resolve(maps.emissive, self.white),
        ]
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
