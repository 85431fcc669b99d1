//! [`RenderSettings`]: every tunable of the renderer in one place.

use std::path::PathBuf;

use crate::debug_lines::DebugCategories;

/// Renderer settings. Change them with [`crate::Renderer::set_settings`]; targets pick up a
/// new MSAA count on their next frame.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderSettings {
    /// MSAA samples per pixel: 1 (off) or 4. Default 4. Falls back to 1, with a warning,
    /// where the adapter cannot multisample the target format. Higher costs fill rate and
    /// memory; golden-image tests use 1 so output is identical across rasterisers.
    pub msaa_samples: u32,
    /// Linear RGBA colour the targets are cleared to. Default dark grey-blue.
    pub clear_color: [f64; 4],
    /// Batch objects by (mesh, shading, texture) into instanced draws. Default true. Off
    /// issues one draw per object (for comparison only: far slower with many objects).
    pub instancing: bool,
    /// Skip objects whose bounding sphere lies outside the view. Default true.
    pub frustum_culling: bool,
    /// Draw the editor grid when the scene asks for it. Default true.
    pub grid: bool,
    /// Grid cell size in metres. Default 1.0. Too small turns the grid into noise far away.
    pub grid_cell_size: f32,
    /// Every Nth grid line is a major line. Default 10.
    pub grid_major_every: u32,
    /// Distance in metres at which the grid has faded out. Default 60.
    pub grid_fade_distance: f32,
    /// Debug-line categories drawn. Default all.
    pub debug_categories: DebugCategories,
    /// Width of debug lines in pixels. Default 1.5.
    pub debug_line_width: f32,
    /// Folder the WGSL shaders are read from (and re-read by
    /// [`crate::Renderer::reload_shaders`]). `None` uses the copies embedded in the binary.
    /// Default `None`.
    pub shader_dir: Option<PathBuf>,
}

impl Default for RenderSettings {
    fn default() -> Self {
        Self {
            msaa_samples: 4,
            clear_color: [0.05, 0.06, 0.08, 1.0],
            instancing: true,
            frustum_culling: true,
            grid: true,
            grid_cell_size: 1.0,
            grid_major_every: 10,
            grid_fade_distance: 60.0,
            debug_categories: DebugCategories::ALL,
            debug_line_width: 1.5,
            shader_dir: None,
        }
    }
}

impl RenderSettings {
    /// Settings for deterministic output (golden images): MSAA off.
    #[must_use]
    pub fn deterministic() -> Self {
        Self {
            msaa_samples: 1,
            ..Self::default()
        }
    }

    /// Sets the MSAA sample count.
    #[must_use]
    pub fn with_msaa(mut self, samples: u32) -> Self {
        self.msaa_samples = samples;
        self
    }

    /// Sets the folder shaders are read from.
    #[must_use]
    pub fn with_shader_dir(mut self, dir: impl Into<PathBuf>) -> Self {
        self.shader_dir = Some(dir.into());
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The defaults written in the field docs must be the real ones.
    #[test]
    fn documented_defaults_match_default() {
        let d = RenderSettings::default();
        assert_eq!(d.msaa_samples, 4);
        assert!(d.instancing && d.frustum_culling && d.grid);
        assert_eq!(
            (d.grid_cell_size, d.grid_major_every, d.grid_fade_distance),
            (1.0, 10, 60.0)
        );
        assert_eq!(
            (d.debug_categories, d.debug_line_width),
            (DebugCategories::ALL, 1.5)
        );
        assert_eq!(d.shader_dir, None);
        assert_eq!(RenderSettings::deterministic().msaa_samples, 1);
    }
}
