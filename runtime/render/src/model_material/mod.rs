//! What a model file says about its materials, carried whole in the loaded model — also the
//! parts the renderer does not draw yet (it draws base colour × base-colour texture; a
//! physically based renderer can later read metallic, roughness, normal, occlusion,
//! emissive and alpha from here).
//!
//! - `model_material`: [`ModelMaterial`], metallic-roughness parameters and texture slots.
//! - `texture_ref`: [`TextureRef`], a texture slot: image, UV set, transform, sampler.
//! - `image_source`: [`ImageSource`], an image file or an image inside a model file.
//! - `uv_transform`: [`UvTransform`], offset / rotation / scale of texture coordinates.
//! - `sampler_desc`: [`SamplerDesc`] and [`WrapMode`], how a texture is filtered and tiled.
//! - `alpha_mode`: [`AlphaMode`], opaque, masked or blended.

mod alpha_mode;
mod image_source;
#[allow(clippy::module_inception)]
mod model_material;
mod sampler_desc;
mod texture_ref;
mod uv_transform;

pub use alpha_mode::AlphaMode;
pub use image_source::ImageSource;
pub use model_material::ModelMaterial;
pub use sampler_desc::{SamplerDesc, WrapMode};
pub use texture_ref::TextureRef;
pub use uv_transform::UvTransform;
