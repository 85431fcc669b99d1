//! [`InstanceRaw`]: one object's transform and colour on the GPU (`InstanceIn` in WGSL).

use glam::{Mat3, Mat4};

/// Model matrix, normal matrix (inverse transpose, padded to vec4 columns) and colour.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct InstanceRaw {
    model: [[f32; 4]; 4],
    normal: [[f32; 4]; 3],
    color: [f32; 4],
}

impl InstanceRaw {
    pub(crate) fn new(model: &Mat4, color: [f32; 4]) -> Self {
        let linear = Mat3::from_mat4(*model);
        let det = linear.determinant();
        // A singular transform (zero scale) has no normal matrix; its normals do not matter.
        let normal = if det.abs() > f32::EPSILON {
            linear.inverse().transpose()
        } else {
            linear
        };
        Self {
            model: model.to_cols_array_2d(),
            normal: [
                normal.x_axis.extend(0.0).to_array(),
                normal.y_axis.extend(0.0).to_array(),
                normal.z_axis.extend(0.0).to_array(),
            ],
            color,
        }
    }
}
