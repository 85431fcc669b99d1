//! [`DirectionalLight`]: a light infinitely far away (the sun).

use glam::Vec3;

use super::light_shadows::LightShadows;

/// A light infinitely far away. Casts cascaded shadows by default.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectionalLight {
    /// Direction the light travels, world space (normalised by the renderer).
    pub direction: Vec3,
    /// Linear RGB colour.
    pub color: Vec3,
    /// Intensity: a white surface facing the light is this bright.
    pub intensity: f32,
    /// Shadows (on by default).
    pub shadows: LightShadows,
}

impl Default for DirectionalLight {
    /// White sun from above, slightly from the front-left, casting shadows.
    fn default() -> Self {
        Self {
            direction: Vec3::new(-0.4, -1.0, -0.3),
            color: Vec3::ONE,
            intensity: 1.0,
            shadows: LightShadows::directional(),
        }
    }
}

impl DirectionalLight {
    /// A white light of intensity 1 travelling along `direction`, casting shadows.
    #[must_use]
    pub fn new(direction: Vec3) -> Self {
        Self {
            direction,
            ..Self::default()
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

    /// Sets the shadow settings.
    #[must_use]
    pub fn with_shadows(mut self, shadows: LightShadows) -> Self {
        self.shadows = shadows;
        self
    }
}
