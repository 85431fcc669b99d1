//! Textures: decoding (PNG, JPEG; header checked first), mipmaps, the cache and fallbacks.
//!
//! - `texture_handle`: [`TextureHandle`], names a texture uploaded to a renderer.
//! - `texture_load_error`: [`TextureLoadError`], why an image file failed.
//! - `texture_source`: [`TextureSource`], an image decoded on the CPU with its mip chain
//!   (any thread); [`decode_texture_bytes`].
//! - `mipmaps`: CPU mip chain generation.
//! - `gpu_texture`: a texture with its view and bind group.
//! - `texture_cache`: every uploaded texture, by source, plus the white and checker fallbacks.

mod gpu_texture;
mod mipmaps;
mod texture_cache;
mod texture_handle;
mod texture_load_error;
mod texture_source;

pub(crate) use texture_cache::TextureCache;
pub use texture_handle::TextureHandle;
pub use texture_load_error::TextureLoadError;
pub(crate) use texture_source::decode_texture;
pub use texture_source::{decode_texture_bytes, TextureSource, MAX_DECODED_PIXELS};
