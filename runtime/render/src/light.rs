//! [`Lights`] of a scene: ambient, one [`DirectionalLight`] sun, up to
//! [`MAX_POINT_LIGHTS`] [`PointLight`]s. Three small plain-data types kept together because
//! they are only ever filled together.

use glam::Vec3;

/// Most point lights a frame can use; extra lights are ignored (with a debug log).
pub const MAX_POINT_LIGHTS: usize = 8;

/// A light infinitely far away (the sun).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectionalLight {
    /// Direction the light travels, world space (normalised by the renderer).
    pub direction: Vec3,
    /// Linear RGB colour.
    pub color: Vec3,
    /// Intensity multiplier (1.0 = colour as given).
    pub intensity: f32,
}

impl Default for DirectionalLight {
    /// White sun from above, slightly from the front-left.
    fn default() -> Self {
        Self {
            direction: Vec3::new(-0.4, -1.0, -0.3),
            color: Vec3::ONE,
            intensity: 1.0,
        }
    }
}

/// A light at a point, fading to zero at `range`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    /// World position in metres.
    pub position: Vec3,
    /// Linear RGB colour.
    pub color: Vec3,
    /// Intensity multiplier; the light also falls off as 1 / (1 + d²).
    pub intensity: f32,
    /// Distance in metres at which the light reaches zero.
    pub range: f32,
}

impl PointLight {
    /// A white point light at `position` with intensity 1 and a 10 m range.
    #[must_use]
    pub fn new(position: Vec3) -> Self {
        Self {
            position,
            color: Vec3::ONE,
            intensity: 1.0,
            range: 10.0,
        }
    }

    /// Sets the colour.
    #[must_use]
    pub fn with_color(mut self, color: Vec3) -> Self {
        self.color = color;
        self
    }

    /// Sets the intensity.
    #[must_use]
    pub fn with_intensity(mut self, intensity: f32) -> Self {
        self.intensity = intensity;
        self
    }

    /// Sets the range in metres.
    #[must_use]
    pub fn with_range(mut self, range: f32) -> Self {
        self.range = range;
        self
    }
}

/// All lights of a frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Lights {
    /// Ambient light, linear RGB × intensity, added to every lit surface.
    pub ambient: Vec3,
    /// The sun, if any.
    pub sun: Option<DirectionalLight>,
    /// Point lights; only the first [`MAX_POINT_LIGHTS`] are used.
    pub points: Vec<PointLight>,
}

impl Default for Lights {
    /// A dim ambient (0.15) and the default sun, no point lights.
    fn default() -> Self {
        Self {
            ambient: Vec3::splat(0.15),
            sun: Some(DirectionalLight::default()),
            points: Vec::new(),
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
        }
    }
}
