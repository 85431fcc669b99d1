//! [`Material`]: how an object looks: a metallic-roughness material, its maps, its alpha
//! mode and its shading mode.

use crate::model_material::AlphaMode;
use crate::shading_mode::ShadingMode;
use crate::texture::TextureHandle;

/// What an object looks like: glTF's metallic-roughness model. Plain data, cheap to copy.
///
/// Objects are batched by (mesh, shading mode, alpha mode, sidedness, maps); the factors
/// (colour, metallic, roughness, emissive, …) travel per instance, so objects that differ only
/// in them still share one draw call.
///
/// Maps multiply their factor (glTF): base colour × `texture` (sRGB), metallic × blue and
/// roughness × green of `metallic_roughness_texture` (linear), occlusion from the red channel
/// of `occlusion_texture`, emissive × `emissive_texture` (sRGB). `normal_texture` is a
/// tangent-space normal map (linear, +Y up, as glTF and Blender write them).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Linear RGBA base colour; alpha is used by [`AlphaMode::Mask`] and [`AlphaMode::Blend`].
    pub color: [f32; 4],
    /// Base colour (albedo) map, sRGB; `None` means white.
    pub texture: Option<TextureHandle>,
    /// Shading mode.
    pub shading: ShadingMode,
    /// Metalness, 0 (dielectric) ..= 1 (metal).
    pub metallic: f32,
    /// Perceptual roughness, 0 (mirror) ..= 1 (fully rough).
    pub roughness: f32,
    /// Metallic (blue) and roughness (green) map, linear.
    pub metallic_roughness_texture: Option<TextureHandle>,
    /// Tangent-space normal map, linear.
    pub normal_texture: Option<TextureHandle>,
    /// Strength of the normal map (glTF `scale`): 0 flat, 1 as baked.
    pub normal_scale: f32,
    /// Ambient-occlusion map (red channel), linear.
    pub occlusion_texture: Option<TextureHandle>,
    /// Occlusion strength, 0 (none) ..= 1 (full).
    pub occlusion_strength: f32,
    /// Emitted light, linear RGB (may exceed 1: HDR).
    pub emissive: [f32; 3],
    /// Emissive map, sRGB.
    pub emissive_texture: Option<TextureHandle>,
    /// Opaque, masked (alpha below the cutoff is cut away) or blended (sorted back to front).
    pub alpha_mode: AlphaMode,
    /// Whether back faces are drawn (lit with the flipped normal).
    pub double_sided: bool,
}

impl Material {
    /// Roughness of [`Material::color`]: a soft plastic.
    pub const DEFAULT_ROUGHNESS: f32 = 0.5;

    /// A dielectric material with this linear RGB colour (metallic 0, roughness 0.5), no maps,
    /// [`ShadingMode::Lit`].
    #[must_use]
    pub fn color(r: f32, g: f32, b: f32) -> Self {
        Self {
            color: [r, g, b, 1.0],
            texture: None,
            shading: ShadingMode::Lit,
            metallic: 0.0,
            roughness: Self::DEFAULT_ROUGHNESS,
            metallic_roughness_texture: None,
            normal_texture: None,
            normal_scale: 1.0,
            occlusion_texture: None,
            occlusion_strength: 1.0,
            emissive: [0.0; 3],
            emissive_texture: None,
            alpha_mode: AlphaMode::Opaque,
            double_sided: false,
        }
    }

    /// A white [`ShadingMode::Lit`] material with this base colour map.
    #[must_use]
    pub fn textured(texture: TextureHandle) -> Self {
        Self {
            texture: Some(texture),
            ..Self::color(1.0, 1.0, 1.0)
        }
    }

    /// Sets the shading mode.
    #[must_use]
    pub fn with_shading(mut self, shading: ShadingMode) -> Self {
        self.shading = shading;
        self
    }

    /// Sets the base colour map.
    #[must_use]
    pub fn with_texture(mut self, texture: Option<TextureHandle>) -> Self {
        self.texture = texture;
        self
    }

    /// Sets metalness and roughness.
    #[must_use]
    pub fn with_metallic_roughness(mut self, metallic: f32, roughness: f32) -> Self {
        self.metallic = metallic;
        self.roughness = roughness;
        self
    }

    /// Sets the emitted light (linear RGB, HDR).
    #[must_use]
    pub fn with_emissive(mut self, emissive: [f32; 3]) -> Self {
        self.emissive = emissive;
        self
    }

    /// Sets the tangent-space normal map.
    #[must_use]
    pub fn with_normal_map(mut self, texture: Option<TextureHandle>, scale: f32) -> Self {
        self.normal_texture = texture;
        self.normal_scale = scale;
        self
    }

    /// Sets the alpha mode.
    #[must_use]
    pub fn with_alpha_mode(mut self, alpha_mode: AlphaMode) -> Self {
        self.alpha_mode = alpha_mode;
        self
    }

    /// Sets the alpha (colour's fourth channel).
    #[must_use]
    pub fn with_alpha(mut self, alpha: f32) -> Self {
        self.color[3] = alpha;
        self
    }

    /// Draws back faces too.
    #[must_use]
    pub fn with_double_sided(mut self, double_sided: bool) -> Self {
        self.double_sided = double_sided;
        self
    }

    /// Whether this material is blended (drawn after opaque ones, back to front, casting
    /// no shadow).
    #[must_use]
    pub fn is_blended(&self) -> bool {
        matches!(self.alpha_mode, AlphaMode::Blend) && self.shading.uses_alpha()
    }
}

impl Default for Material {
    /// Light grey plastic, lit.
    fn default() -> Self {
        Self::color(0.8, 0.8, 0.8)
    }
}
