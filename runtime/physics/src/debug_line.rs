//! [`DebugLine`]: one coloured line segment for a renderer's debug draw.

use glam::Vec3;

/// A world-space line segment with an RGBA colour (linear, 0..1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DebugLine {
    /// Start point.
    pub a: Vec3,
    /// End point.
    pub b: Vec3,
    /// RGBA colour.
    pub color: [f32; 4],
}
