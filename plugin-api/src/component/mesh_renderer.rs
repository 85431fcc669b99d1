//! [`MeshRenderer`] and [`Material`]: what an entity looks like.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

use super::builtin::{finite, FileRefs, HostRefs};
use crate::{AlphaMode, Builtin, InvalidValue, MeshId, ShadingMode, TextureId};

/// How a drawn mesh looks: a physically based (metallic-roughness, as glTF) material.
///
/// Built-in shapes use every field as given. A model file keeps the materials its file
/// describes: `color` multiplies each part's colour, `texture` (when set) replaces its base
/// colour map, `emissive` adds to its own, an `alpha_mode` other than
/// [`AlphaMode::Opaque`] replaces its own and `double_sided` adds to its own; its metallic,
/// roughness and maps stay the file's.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Material {
    /// Linear RGBA base colour (multiplies the texture); alpha is used by
    /// [`AlphaMode::Mask`] and [`AlphaMode::Blend`].
    pub color: [f32; 4],
    /// Albedo texture; [`TextureId::NONE`] uses the model's own texture, if any.
    pub texture: TextureId,
    /// How it is shaded.
    pub shading: ShadingMode,
    /// Metalness, 0 (dielectric: plastic, wood, stone) ..= 1 (metal). Default 0.
    pub metallic: f32,
    /// Perceptual roughness, 0 (mirror) ..= 1 (fully matte). Default 0.5.
    pub roughness: f32,
    /// Light the surface emits, linear RGB; may exceed 1 (HDR: it glows through tone
    /// mapping). Default black.
    pub emissive: [f32; 3],
    /// How alpha is used. Default [`AlphaMode::Opaque`].
    pub alpha_mode: AlphaMode,
    /// Alpha below which [`AlphaMode::Mask`] cuts the surface away, 0..=1. Default 0.5.
    pub alpha_cutoff: f32,
    /// Whether back faces are drawn too (leaves, cloth, open meshes). Default false.
    pub double_sided: bool,
}

impl Default for Material {
    fn default() -> Self {
        Self::color(0.8, 0.8, 0.8)
    }
}

impl Material {
    /// Roughness of [`Material::color`]: a soft plastic.
    pub const DEFAULT_ROUGHNESS: f32 = 0.5;
    /// Alpha cutoff of [`Material::color`] (glTF's default).
    pub const DEFAULT_ALPHA_CUTOFF: f32 = 0.5;

    /// A lit, untextured, dielectric material of colour (r, g, b), linear: metallic 0,
    /// roughness 0.5, opaque, single-sided.
    pub const fn color(r: f32, g: f32, b: f32) -> Self {
        Self {
            color: [r, g, b, 1.0],
            texture: TextureId::NONE,
            shading: ShadingMode::Lit,
            metallic: 0.0,
            roughness: Self::DEFAULT_ROUGHNESS,
            emissive: [0.0; 3],
            alpha_mode: AlphaMode::Opaque,
            alpha_cutoff: Self::DEFAULT_ALPHA_CUTOFF,
            double_sided: false,
        }
    }

    /// Returns this material with metalness and roughness (each 0..=1).
    #[must_use]
    pub const fn with_metallic_roughness(mut self, metallic: f32, roughness: f32) -> Self {
        self.metallic = metallic;
        self.roughness = roughness;
        self
    }

    /// Returns this material emitting `emissive` (linear RGB, may exceed 1).
    #[must_use]
    pub const fn with_emissive(mut self, emissive: [f32; 3]) -> Self {
        self.emissive = emissive;
        self
    }

    /// Returns this material blended with alpha `alpha` ([`AlphaMode::Blend`]).
    #[must_use]
    pub const fn with_blend(mut self, alpha: f32) -> Self {
        self.color[3] = alpha;
        self.alpha_mode = AlphaMode::Blend;
        self
    }

    /// Returns this material with `alpha_mode` and, for [`AlphaMode::Mask`], `cutoff`.
    #[must_use]
    pub const fn with_alpha_mode(mut self, alpha_mode: AlphaMode, cutoff: f32) -> Self {
        self.alpha_mode = alpha_mode;
        self.alpha_cutoff = cutoff;
        self
    }

    /// Returns this material drawing back faces too.
    #[must_use]
    pub const fn with_double_sided(mut self, double_sided: bool) -> Self {
        self.double_sided = double_sided;
        self
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

/// A [`MeshRenderer`] as scene files and state dumps write it: meshes and textures by file
/// path (ids are only valid while a host runs).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeshRendererFile {
    /// A built-in shape (`cube`, `sphere`, `plane`, `capsule`, `cylinder`) or a model file.
    pub mesh: String,
    /// Linear RGBA colour.
    #[serde(default = "white")]
    pub color: [f32; 4],
    /// An albedo texture file.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub texture: Option<String>,
    /// How it is shaded.
    #[serde(default)]
    pub shading: ShadingMode,
    /// Metalness, 0..=1.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub metallic: f32,
    /// Perceptual roughness, 0..=1.
    #[serde(
        default = "default_roughness",
        skip_serializing_if = "is_default_roughness"
    )]
    pub roughness: f32,
    /// Emitted light, linear RGB.
    #[serde(default, skip_serializing_if = "is_black")]
    pub emissive: [f32; 3],
    /// How alpha is used.
    #[serde(default, skip_serializing_if = "is_opaque")]
    pub alpha_mode: AlphaMode,
    /// Alpha cutoff of [`AlphaMode::Mask`].
    #[serde(default = "default_cutoff", skip_serializing_if = "is_default_cutoff")]
    pub alpha_cutoff: f32,
    /// Whether back faces are drawn.
    #[serde(default, skip_serializing_if = "is_false")]
    pub double_sided: bool,
    /// Whether it is drawn.
    #[serde(default = "yes")]
    pub visible: bool,
}

fn default_roughness() -> f32 {
    Material::DEFAULT_ROUGHNESS
}

fn default_cutoff() -> f32 {
    Material::DEFAULT_ALPHA_CUTOFF
}

fn is_zero(v: &f32) -> bool {
    *v == 0.0
}

fn is_default_roughness(v: &f32) -> bool {
    *v == Material::DEFAULT_ROUGHNESS
}

fn is_default_cutoff(v: &f32) -> bool {
    *v == Material::DEFAULT_ALPHA_CUTOFF
}

fn is_black(c: &[f32; 3]) -> bool {
    *c == [0.0; 3]
}

fn is_opaque(mode: &AlphaMode) -> bool {
    *mode == AlphaMode::Opaque
}

fn is_false(b: &bool) -> bool {
    !*b
}

/// Checks a factor lies in 0..=1.
fn unit(field: &'static str, value: f32) -> Result<(), InvalidValue> {
    finite(field, &[value])?;
    if (0.0..=1.0).contains(&value) {
        Ok(())
    } else {
        Err(InvalidValue::invalid(
            field,
            format!("is {value}, outside 0..=1"),
        ))
    }
}

fn white() -> [f32; 4] {
    [1.0; 4]
}

fn yes() -> bool {
    true
}

impl Builtin for MeshRenderer {
    const NAME: &'static str = "MeshRenderer";
    type File = MeshRendererFile;

    fn tool_default() -> Option<Self> {
        Some(MeshRenderer::new(MeshId::CUBE))
    }

    fn validate(&self, refs: &dyn HostRefs) -> Result<(), InvalidValue> {
        let m = &self.material;
        finite("material.color", &m.color)?;
        finite("material.emissive", &m.emissive)?;
        unit("material.metallic", m.metallic)?;
        unit("material.roughness", m.roughness)?;
        unit("material.alpha_cutoff", m.alpha_cutoff)?;
        if !refs.knows_mesh(self.mesh) {
            return Err(InvalidValue::invalid(
                "mesh",
                format!("is mesh id {}, which this host did not give", self.mesh.0),
            ));
        }
        if !refs.knows_texture(self.material.texture) {
            return Err(InvalidValue::invalid(
                "material.texture",
                format!(
                    "is texture id {}, which this host did not give",
                    self.material.texture.0
                ),
            ));
        }
        Ok(())
    }

    fn to_file(&self, refs: &dyn HostRefs) -> MeshRendererFile {
        let mesh = MeshId::BUILTIN
            .iter()
            .find(|(id, _)| *id == self.mesh)
            .map(|(_, name)| (*name).to_owned())
            .or_else(|| refs.mesh_file(self.mesh))
            .unwrap_or_else(|| "cube".to_owned());
        MeshRendererFile {
            mesh,
            color: self.material.color,
            texture: refs.texture_file(self.material.texture),
            shading: self.material.shading,
            metallic: self.material.metallic,
            roughness: self.material.roughness,
            emissive: self.material.emissive,
            alpha_mode: self.material.alpha_mode,
            alpha_cutoff: self.material.alpha_cutoff,
            double_sided: self.material.double_sided,
            visible: self.visible,
        }
    }

    fn from_file(file: MeshRendererFile, refs: &mut dyn FileRefs) -> Result<Self, InvalidValue> {
        if file.mesh.is_empty() {
            return Err(InvalidValue::invalid("mesh", "names no mesh"));
        }
        let mesh = MeshId::BUILTIN
            .iter()
            .find(|(_, name)| *name == file.mesh)
            .map(|(id, _)| *id)
            .unwrap_or_else(|| refs.mesh(&file.mesh));
        let texture = file
            .texture
            .as_deref()
            .map_or(TextureId::NONE, |path| refs.texture(path));
        Ok(MeshRenderer {
            mesh,
            material: Material {
                color: file.color,
                texture,
                shading: file.shading,
                metallic: file.metallic,
                roughness: file.roughness,
                emissive: file.emissive,
                alpha_mode: file.alpha_mode,
                alpha_cutoff: file.alpha_cutoff,
                double_sided: file.double_sided,
            },
            visible: file.visible,
        })
    }
}
