//! [`LineRaw`]: one debug line on the GPU (`LineIn` in `debug_lines.wgsl`), camera-relative.

use glam::Vec3;

use crate::debug_lines::DebugLine;

/// Start, width in pixels, end, colour.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct LineRaw {
    start: [f32; 3],
    width_px: f32,
    end: [f32; 3],
    color: [f32; 4],
}

impl LineRaw {
    /// `line` with its ends made relative to `origin` (the camera position).
    pub(crate) fn new(line: &DebugLine, width_px: f32, origin: Vec3) -> Self {
        Self {
            start: (line.start - origin).to_array(),
            width_px,
            end: (line.end - origin).to_array(),
            color: line.color,
        }
    }
}
