//! [`MeshRenderer`] and [`Material`]: what an entity looks like.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

use crate::{MeshId, ShadingMode, TextureId};

/// Colour, texture and shading of a drawn mesh.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Material {
    /// Linear RGBA colour (multiplies the texture).
    pub color: [f32; 4],
    /// Albedo texture; [`TextureId::NONE`] uses the model's own texture, if any.
    pub texture: TextureId,
    /// How it is shaded.
    pub shading: ShadingMode,
}

impl Default for Material {
    fn default() -> Self {
        Self::color(0.8, 0.8, 0.8)
    }
}

impl Material {
    /// A lit, untextured material of colour (r, g, b), linear.
    pub const fn color(r: f32, g: f32, b: f32) -> Self {
        Self {
            color: [r, g, b, 1.0],
            texture: TextureId::NONE,
            shading: ShadingMode::Lit,
        }
    }

    /// Returns this material with `shading`.
    #[must_use]
    pub const fn with_shading(mut self, shading: ShadingMode) -> Self {
        self.shading = shading;
        self
    }

    /// Returns this material with `texture`.
    #[must_use]
    pub const fn with_texture(mut self, texture: TextureId) -> Self {
        self.texture = texture;
        self
    }
}

/// Draws a mesh at the entity's [`Transform`](crate::Transform).
///
/// `ctx.spawn((Transform::from_xyz(0.0, 1.0, 0.0), MeshRenderer::new(MeshId::CUBE)))`
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct MeshRenderer {
    /// The mesh.
    pub mesh: MeshId,
    /// Its material.
    pub material: Material,
    /// Whether it is drawn.
    pub visible: bool,
}

impl MeshRenderer {
    /// A visible mesh with the default material.
    pub const fn new(mesh: MeshId) -> Self {
        Self {
            mesh,
            material: Material::color(0.8, 0.8, 0.8),
            visible: true,
        }
    }

    /// Returns this renderer with `material`.
    #[must_use]
    pub const fn with_material(mut self, material: Material) -> Self {
        self.material = material;
        self
    }
}
