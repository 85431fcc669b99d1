//! [`DebugLine`]: a line segment drawn for one frame, for debugging.

use abi_stable::StableAbi;
use glam::Vec3;

/// A coloured segment drawn on top of the scene for one frame
/// ([`Ctx::draw_debug_lines`](crate::Ctx::draw_debug_lines)).
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq)]
pub struct DebugLine {
    /// Start, world space.
    #[sabi(unsafe_opaque_field)]
    pub start: Vec3,
    /// End, world space.
    #[sabi(unsafe_opaque_field)]
    pub end: Vec3,
    /// Linear RGBA colour.
    pub color: [f32; 4],
}

impl DebugLine {
    /// A segment from `start` to `end` in `color`.
    pub const fn new(start: Vec3, end: Vec3, color: [f32; 4]) -> Self {
        Self { start, end, color }
    }
}
