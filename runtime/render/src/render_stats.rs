//! [`RenderStats`]: counters of the last rendered frame, for a diagnostics panel.

use std::time::Duration;

/// What the last [`crate::Renderer::render`] call did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RenderStats {
    /// Draw calls issued (meshes, grid and debug lines).
    pub draw_calls: u32,
    /// Triangles submitted for meshes (index count / 3 × instances, all batches).
    pub triangles: u64,
    /// Mesh instances drawn (objects that survived culling).
    pub instances: u32,
    /// Objects removed by frustum culling.
    pub culled: u32,
    /// Distinct (mesh, shading, texture) batches drawn.
    pub batches: u32,
    /// Debug lines drawn (after category filtering).
    pub debug_lines: u32,
    /// CPU time spent culling, batching and filling the instance buffers.
    pub cpu_prepare_time: Duration,
    /// True when the frame was skipped (minimised window, surface not available).
    pub skipped: bool,
}
