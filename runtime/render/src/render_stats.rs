//! [`RenderStats`]: counters of the last rendered frame, for a diagnostics panel.

use std::time::Duration;

/// What the last [`crate::Renderer::render`] call did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RenderStats {
    /// Draw calls of the camera pass (meshes, sky, grid and debug lines; tone mapping not
    /// counted).
    pub draw_calls: u32,
    /// Draw calls of all shadow passes together (instanced like the camera's).
    pub shadow_draw_calls: u32,
    /// Shadow passes drawn (directional cascades, spot lights, point-light cube faces).
    pub shadow_views: u32,
    /// Instances drawn by all shadow passes together.
    pub shadow_instances: u32,
    /// Blended (transparent) objects drawn, back to front.
    pub blended: u32,
    /// Triangles submitted for meshes (index count / 3 × instances, all batches).
    pub triangles: u64,
    /// Mesh instances drawn (objects that survived culling).
    pub instances: u32,
    /// Objects removed by frustum culling.
    pub culled: u32,
    /// Distinct (mesh, shading, alpha, sidedness, maps) batches of the camera pass.
    pub batches: u32,
    /// Debug lines drawn (after category filtering).
    pub debug_lines: u32,
    /// CPU time spent fitting shadow views, culling for every view, batching and filling the
    /// object, instance and uniform buffers.
    pub cpu_prepare_time: Duration,
    /// True when the frame was skipped (minimised window, surface not available).
    pub skipped: bool,
}
