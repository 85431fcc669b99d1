//! [`ObjectRaw`]: one object on the GPU (`Object` in `common.wgsl`), read from a storage
//! buffer by every pass that draws it (the camera's and each shadow view's).

use glam::{Mat4, Vec3};

use crate::material::Material;

/// A camera-relative affine transform (three rows) and the material's per-object factors.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct ObjectRaw {
    /// Rows of the model matrix with its translation made relative to the camera.
    rows: [[f32; 4]; 3],
    /// Linear RGBA base colour.
    color: [f32; 4],
    /// Metallic, roughness, normal scale, occlusion strength.
    pbr: [f32; 4],
    /// Emissive RGB, alpha cutoff.
    emissive: [f32; 4],
}

impl ObjectRaw {
    /// `model` placed relative to `origin` (the camera position): the subtraction happens
    /// here, in world units, so the GPU only ever sees small numbers.
    pub(crate) fn new(model: &Mat4, origin: Vec3, material: &Material) -> Self {
        let t = model.w_axis.truncate() - origin;
        let (x, y, z) = (model.x_axis, model.y_axis, model.z_axis);
        Self {
            rows: [
                [x.x, y.x, z.x, t.x],
                [x.y, y.y, z.y, t.y],
                [x.z, y.z, z.z, t.z],
            ],
            color: material.color,
            pbr: [
                material.metallic.clamp(0.0, 1.0),
                material.roughness.clamp(0.0, 1.0),
                material.normal_scale,
                material.occlusion_strength.clamp(0.0, 1.0),
            ],
            emissive: [
                material.emissive[0],
                material.emissive[1],
                material.emissive[2],
                material.alpha_mode.cutoff(),
            ],
        }
    }
}

#[cfg(test)]
impl ObjectRaw {
    /// The relative translation's z (tests).
    pub(crate) fn z(&self) -> f32 {
        self.rows[2][3]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A far object's translation reaches the GPU as its small offset from the camera.
    #[test]
    fn translation_is_made_relative_to_the_camera() {
        let origin = Vec3::new(100_000.0, 0.0, -50_000.0);
        let model = Mat4::from_translation(origin + Vec3::new(1.5, 2.0, -3.25));
        let raw = ObjectRaw::new(&model, origin, &Material::default());
        assert_eq!(
            [raw.rows[0][3], raw.rows[1][3], raw.rows[2][3]],
            [1.5, 2.0, -3.25]
        );
    }
}
