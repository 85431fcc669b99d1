//! [`Model`] and [`ModelPart`]: a loaded model file, one part per mesh and material.

use glam::Mat4;

use super::mesh_handle::MeshHandle;
use crate::material::Material;
use crate::model_material::ModelMaterial;
use crate::render_scene::DrawObject;

/// One mesh of a model with its material (an OBJ file with several materials gives several
/// parts; a glTF file one per primitive).
#[derive(Clone, Debug, PartialEq)]
pub struct ModelPart {
    /// Object / group / node name from the file.
    pub name: String,
    /// The uploaded mesh.
    pub mesh: MeshHandle,
    /// What the renderer draws it with: the file material's base colour and base-colour
    /// texture, [`crate::ShadingMode::Lit`].
    pub material: Material,
    /// The material as the file describes it, whole (metallic, roughness, normal,
    /// occlusion, emissive, alpha…), for what the renderer does not draw yet.
    pub file_material: ModelMaterial,
    /// Part space → model space.
    pub transform: Mat4,
}

impl ModelPart {
    /// A part drawn with `material` at the model's origin.
    #[must_use]
    pub fn new(name: impl Into<String>, mesh: MeshHandle, material: Material) -> Self {
        Self {
            name: name.into(),
            mesh,
            material,
            file_material: ModelMaterial::default(),
            transform: Mat4::IDENTITY,
        }
    }
}

/// A loaded model: its parts share one transform. Cheap to clone (handles and material
/// descriptions).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Model {
    /// Parts, in file order.
    pub parts: Vec<ModelPart>,
}

impl Model {
    /// One [`DrawObject`] per part, placed by `transform` (model → world).
    pub fn draw_objects(&self, transform: Mat4) -> impl Iterator<Item = DrawObject> + '_ {
        self.parts.iter().map(move |part| DrawObject {
            mesh: part.mesh,
            material: part.material,
            transform: transform * part.transform,
        })
    }
}
