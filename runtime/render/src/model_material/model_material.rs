//! [`ModelMaterial`]: a material as its model file describes it.

use super::alpha_mode::AlphaMode;
use super::texture_ref::TextureRef;

/// A material as the model file describes it, in glTF's metallic-roughness terms (OBJ/MTL
/// maps onto them: `Kd` → base colour, `d`/`Tr` → alpha, `map_Kd` → base-colour texture,
/// `norm` / `map_Bump` → normal / bump texture, `Ke` → emissive).
///
/// Drawn today: `base_color` × `base_color_texture` (lit). Carried, not drawn yet: the rest.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelMaterial {
    /// Material name from the file.
    pub name: String,
    /// Linear RGBA base colour factor.
    pub base_color: [f32; 4],
    /// Base-colour (albedo) texture, sRGB.
    pub base_color_texture: Option<TextureRef>,
    /// Metalness, 0..1.
    pub metallic: f32,
    /// Perceptual roughness, 0..1.
    pub roughness: f32,
    /// Metallic (blue) and roughness (green) texture.
    pub metallic_roughness_texture: Option<TextureRef>,
    /// Tangent-space normal map.
    pub normal_texture: Option<TextureRef>,
    /// Normal map strength (glTF `scale`).
    pub normal_scale: f32,
    /// Height (bump) map (OBJ `map_Bump`/`bump`), with its multiplier in `bump_scale`.
    pub bump_texture: Option<TextureRef>,
    /// Bump multiplier (OBJ `-bm`).
    pub bump_scale: f32,
    /// Ambient occlusion (red channel).
    pub occlusion_texture: Option<TextureRef>,
    /// Occlusion strength, 0..1.
    pub occlusion_strength: f32,
    /// Linear RGB emissive factor.
    pub emissive: [f32; 3],
    /// Multiplier of `emissive` (KHR_materials_emissive_strength).
    pub emissive_strength: f32,
    /// Emissive texture, sRGB.
    pub emissive_texture: Option<TextureRef>,
    /// How alpha is used.
    pub alpha_mode: AlphaMode,
    /// Whether back faces are shown.
    pub double_sided: bool,
    /// KHR_materials_unlit.
    pub unlit: bool,
}

impl Default for ModelMaterial {
    /// glTF's default material: white, fully metallic, fully rough, opaque, single-sided.
    fn default() -> Self {
        Self {
            name: String::new(),
            base_color: [1.0; 4],
            base_color_texture: None,
            metallic: 1.0,
            roughness: 1.0,
            metallic_roughness_texture: None,
            normal_texture: None,
            normal_scale: 1.0,
            bump_texture: None,
            bump_scale: 1.0,
            occlusion_texture: None,
            occlusion_strength: 1.0,
            emissive: [0.0; 3],
            emissive_strength: 1.0,
            emissive_texture: None,
            alpha_mode: AlphaMode::Opaque,
            double_sided: false,
            unlit: false,
        }
    }
}
