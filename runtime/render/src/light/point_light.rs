//! [`PointLight`]: a light at a point, shining in every direction.

use glam::Vec3;

use super::light_shadows::LightShadows;

/// A light at a point: inverse-square falloff, windowed to zero at `range`. Casts cube-map
/// shadows when `shadows.enabled` (off by default).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    /// World position in metres.
    pub position: Vec3,
    /// Linear RGB colour.
    pub color: Vec3,
    /// Intensity: a white surface 1 m away, facing the light, is this bright.
    pub intensity: f32,
    /// Distance in metres at which the light reaches zero.
    pub range: f32,
    /// Shadows (off by default).
    pub shadows: LightShadows,
}

impl PointLight {
    /// A white point light at `position` with intensity 1 and a 10 m range, no shadows.
    #[must_use]
    pub fn new(position: Vec3) -> Self {
        Self {
            position,
            color: Vec3::ONE,
            intensity: 1.0,
            range: 10.0,
            shadows: LightShadows::local(),
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

    /// Sets the shadow settings.
    #[must_use]
    pub fn with_shadows(mut self, shadows: LightShadows) -> Self {
        self.shadows = shadows;
        self
    }
}
