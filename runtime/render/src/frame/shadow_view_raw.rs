//! [`ShadowViewRaw`]: one shadow pass's view-projection (`ShadowView` in `shadow.wgsl`), at
//! a dynamic offset of one uniform buffer.

use glam::Mat4;

/// Bytes between shadow views in their buffer (the dynamic-offset alignment wgpu asks for).
pub(crate) const SHADOW_VIEW_STRIDE: u64 = 256;

/// A shadow view's camera-relative view-projection, padded to [`SHADOW_VIEW_STRIDE`].
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct ShadowViewRaw {
    view_proj: [[f32; 4]; 4],
    padding: [[f32; 4]; 12],
}

impl ShadowViewRaw {
    pub(crate) fn new(view_proj: &Mat4) -> Self {
        Self {
            view_proj: view_proj.to_cols_array_2d(),
            padding: [[0.0; 4]; 12],
        }
    }
}
