//! [`Lights`]: everything that lights one frame.

use glam::Vec3;

use super::directional_light::DirectionalLight;
use super::point_light::PointLight;
use super::spot_light::SpotLight;

/// Most point lights a frame uses; extra ones are ignored (with a debug log).
pub const MAX_POINT_LIGHTS: usize = 8;
/// Most spot lights a frame uses; extra ones are ignored (with a debug log).
pub const MAX_SPOT_LIGHTS: usize = 8;

/// All lights of a frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Lights {
    /// Ambient light: the sky's image-based light (diffuse irradiance and prefiltered
    /// reflections, see [`crate::Sky`]) scaled by this linear RGB × intensity. Zero turns
    /// ambient light off.
    pub ambient: Vec3,
    /// The sun, if any.
    pub sun: Option<DirectionalLight>,
    /// Point lights; only the first [`MAX_POINT_LIGHTS`] are used.
    pub points: Vec<PointLight>,
    /// Spot lights; only the first [`MAX_SPOT_LIGHTS`] are used.
    pub spots: Vec<SpotLight>,
}

impl Default for Lights {
    /// Sky light at 0.3 and the default sun (with shadows), no point or spot lights.
    fn default() -> Self {
        Self {
            ambient: Vec3::splat(0.3),
            sun: Some(DirectionalLight::default()),
            points: Vec::new(),
            spots: Vec::new(),
        }
    }
}

impl Lights {
    /// No light at all: lit objects render black.
    #[must_use]
    pub fn none() -> Self {
        Self {
            ambient: Vec3::ZERO,
            sun: None,
            points: Vec::new(),
            spots: Vec::new(),
        }
    }
}
