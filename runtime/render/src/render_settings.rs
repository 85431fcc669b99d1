//! [`RenderSettings`]: every tunable of the renderer in one place.

use std::path::PathBuf;

use crate::debug_lines::DebugCategories;
use crate::sky::Sky;
use crate::tone_mapping::ToneMapping;

/// Renderer settings. Change them with [`crate::Renderer::set_settings`]; targets pick up a
/// new MSAA count on their next frame.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderSettings {
    /// MSAA samples per pixel: 1 (off) or 4. Default 4. Falls back to 1, with a warning,
    /// where the adapter cannot multisample the target format. Higher costs fill rate and
    /// memory; golden-image tests use 1 so output is identical across rasterisers.
    pub msaa_samples: u32,
    /// Linear RGBA colour behind the scene when `sky_background` is off. Default dark
    /// grey-blue.
    pub clear_color: [f64; 4],
    /// Draw the sky behind the scene (else `clear_color`). Default true.
    pub sky_background: bool,
    /// The sky: image-based ambient light and background. Default [`Sky::default`].
    pub sky: Sky,
    /// Exposure compensation in stops: the HDR frame is scaled by 2^`exposure_ev` before tone
    /// mapping. Default 0. +1 doubles the brightness; too high washes highlights out to
    /// white, too low crushes shadows to black.
    pub exposure_ev: f32,
    /// Operator from HDR to the display. Default [`ToneMapping::AgX`].
    pub tone_mapping: ToneMapping,
    /// Cascades of the directional light's shadow map, 1..=4. Default 3. More cascades keep
    /// shadows sharp further away at one extra shadow pass each.
    pub shadow_cascades: u32,
    /// Side of each directional shadow cascade, texels. Default 2048. Higher is sharper and
    /// costs fill rate and memory (4 bytes per texel per cascade).
    pub shadow_resolution: u32,
    /// Distance from the camera, metres, that directional shadows cover (split between the
    /// cascades). Default 60. Longer spreads the texels thinner.
    pub shadow_distance: f32,
    /// How cascade splits are placed, 0 (uniform) ..= 1 (logarithmic). Default 0.75: most
    /// texels near the camera.
    pub shadow_cascade_lambda: f32,
    /// Side of each point-light cube face and spot-light shadow map, texels. Default 1024.
    pub local_shadow_resolution: u32,
    /// Most spot lights that cast shadows in one frame (the first ones with shadows on).
    /// Default 4.
    pub max_spot_shadows: u32,
    /// Most point lights that cast shadows in one frame (six passes each). Default 2.
    pub max_point_shadows: u32,
    /// Radius of the shadow filter (percentage-closer filtering), texels. Default 1.5.
    /// Larger is softer and blurs small shadows away; 0 gives hard, aliased edges.
    pub shadow_filter_radius: f32,
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
            sky_background: true,
            sky: Sky::default(),
            exposure_ev: 0.0,
            tone_mapping: ToneMapping::AgX,
            shadow_cascades: 3,
            shadow_resolution: 2048,
            shadow_distance: 60.0,
            shadow_cascade_lambda: 0.75,
            local_shadow_resolution: 1024,
            max_spot_shadows: 4,
            max_point_shadows: 2,
            shadow_filter_radius: 1.5,
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

    /// Sets the exposure compensation, stops.
    #[must_use]
    pub fn with_exposure(mut self, exposure_ev: f32) -> Self {
        self.exposure_ev = exposure_ev;
        self
    }

    /// Sets the tone-mapping operator.
    #[must_use]
    pub fn with_tone_mapping(mut self, tone_mapping: ToneMapping) -> Self {
        self.tone_mapping = tone_mapping;
        self
    }

    /// Sets the sky.
    #[must_use]
    pub fn with_sky(mut self, sky: Sky) -> Self {
        self.sky = sky;
        self
    }

    /// The number of directional cascades used: the setting, clamped to 1..=4.
    #[must_use]
    pub fn cascades(&self) -> usize {
        self.shadow_cascades.clamp(1, crate::MAX_CASCADES as u32) as usize
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
        assert!(d.sky_background);
        assert_eq!(d.sky, Sky::default());
        assert_eq!((d.exposure_ev, d.tone_mapping), (0.0, ToneMapping::AgX));
        assert_eq!(
            (
                d.shadow_cascades,
                d.shadow_resolution,
                d.shadow_distance,
                d.shadow_cascade_lambda
            ),
            (3, 2048, 60.0, 0.75)
        );
        assert_eq!(
            (
                d.local_shadow_resolution,
                d.max_spot_shadows,
                d.max_point_shadows,
                d.shadow_filter_radius
            ),
            (1024, 4, 2, 1.5)
        );
        assert_eq!(RenderSettings::deterministic().msaa_samples, 1);
    }
}
