//! Textures: loading (PNG, JPEG), mipmaps, the cache and fallbacks.
//!
//! - `texture_handle`: [`TextureHandle`], names a texture uploaded to a renderer.
//! - `texture_load_error`: [`TextureLoadError`], why an image file failed.
//! - `mipmaps`: CPU mip chain generation.
//! - `gpu_texture`: a texture with its view and bind group.
//! - `texture_cache`: every uploaded texture, by path, plus the white and checker fallbacks.

mod gpu_texture;
mod mipmaps;
mod texture_cache;
mod texture_handle;
mod texture_load_error;

pub(crate) use texture_cache::TextureCache;
pub use texture_handle::TextureHandle;
pub use texture_load_error::TextureLoadError;
