//! [`Model`] and [`ModelPart`]: a loaded model file, one part per material.

use glam::Mat4;

use super::mesh_handle::MeshHandle;
use crate::material::Material;
use crate::render_scene::DrawObject;

/// One mesh of a model with its material (an OBJ file with several materials gives several
/// parts).
#[derive(Clone, Debug, PartialEq)]
pub struct ModelPart {
    /// Object / group name from the file.
    pub name: String,
    /// The uploaded mesh.
    pub mesh: MeshHandle,
    /// Material from the MTL file (colour, texture, [`crate::ShadingMode::Lit`]).
    pub material: Material,
}

/// A loaded model: its parts share one transform. Cheap to clone (handles only).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Model {
    /// Parts, in file order.
    pub parts: Vec<ModelPart>,
}

impl Model {
    /// One [`DrawObject`] per part, all with `transform`.
    pub fn draw_objects(&self, transform: Mat4) -> impl Iterator<Item = DrawObject> + '_ {
        self.parts.iter().map(move |part| DrawObject {
            mesh: part.mesh,
            material: part.material,
            transform,
        })
    }
}
