//! [`TextureRef`]: one texture slot of a material.

use super::image_source::ImageSource;
use super::sampler_desc::SamplerDesc;
use super::uv_transform::UvTransform;
use crate::texture::TextureHandle;

/// A texture slot of a [`super::ModelMaterial`]: which image, read through which UV set,
/// transformed how, sampled how.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureRef {
    /// The image.
    pub image: ImageSource,
    /// Which texture-coordinate set of the mesh (glTF `texCoord`; OBJ has one).
    pub uv_set: u32,
    /// Texture-coordinate transform. For the base-colour slot it is already applied to the
    /// part's mesh (the renderer draws with it); for the others it is carried.
    pub transform: UvTransform,
    /// Sampler.
    pub sampler: SamplerDesc,
    /// The uploaded texture, for slots the renderer draws (base colour); `None` otherwise.
    pub handle: Option<TextureHandle>,
}

impl TextureRef {
    /// A slot reading `image` through UV set 0, untransformed, default sampler.
    #[must_use]
    pub fn new(image: ImageSource) -> Self {
        Self {
            image,
            uv_set: 0,
            transform: UvTransform::IDENTITY,
            sampler: SamplerDesc::default(),
            handle: None,
        }
    }
}
