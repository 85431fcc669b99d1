//! [`MeshRenderer`] and [`Material`]: what an entity looks like.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

use super::builtin::{finite, FileRefs, HostRefs};
use crate::{Builtin, InvalidValue, MeshId, ShadingMode, TextureId};

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
    /// Whether it is drawn.
    #[serde(default = "yes")]
    pub visible: bool,
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
        finite("material.color", &self.material.color)?;
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
            },
            visible: file.visible,
        })
    }
}
