//! [`Material`]: colour, optional texture and shading mode of an object.

use crate::shading_mode::ShadingMode;
use crate::texture::TextureHandle;

/// What an object looks like. Plain data, cheap to copy.
///
/// Objects are batched by (mesh, shading mode, texture); the colour travels per instance,
/// so objects that differ only in colour still share one draw call.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Linear RGBA colour; multiplies the texture in [`ShadingMode::Lit`]. Alpha is ignored
    /// (everything is opaque).
    pub color: [f32; 4],
    /// Albedo texture, used by [`ShadingMode::Lit`]; `None` means plain white.
    pub texture: Option<TextureHandle>,
    /// Shading mode.
    pub shading: ShadingMode,
}

impl Material {
    /// A material with this linear RGB colour, no texture, [`ShadingMode::LitLow`].
    #[must_use]
    pub fn color(r: f32, g: f32, b: f32) -> Self {
        Self {
            color: [r, g, b, 1.0],
            texture: None,
            shading: ShadingMode::LitLow,
        }
    }

    /// A white [`ShadingMode::Lit`] material with this texture.
    #[must_use]
    pub fn textured(texture: TextureHandle) -> Self {
        Self {
            color: [1.0; 4],
            texture: Some(texture),
            shading: ShadingMode::Lit,
        }
    }

    /// Sets the shading mode.
    #[must_use]
    pub fn with_shading(mut self, shading: ShadingMode) -> Self {
        self.shading = shading;
        self
    }

    /// Sets the texture.
    #[must_use]
    pub fn with_texture(mut self, texture: Option<TextureHandle>) -> Self {
        self.texture = texture;
        self
    }
}

impl Default for Material {
    /// Light grey, lit, untextured.
    fn default() -> Self {
        Self::color(0.8, 0.8, 0.8)
    }
}
