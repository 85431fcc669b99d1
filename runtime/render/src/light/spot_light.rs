//! [`SpotLight`]: a light at a point, shining inside a cone.

use glam::Vec3;

use super::light_shadows::LightShadows;

/// A light at a point inside a cone: full strength within `inner_angle` of its direction,
/// fading smoothly to nothing at `outer_angle`; inverse-square falloff windowed to zero at
/// `range`. Casts one shadow map when `shadows.enabled` (off by default).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpotLight {
    /// World position in metres.
    pub position: Vec3,
    /// Direction the cone points, world space (normalised by the renderer).
    pub direction: Vec3,
    /// Linear RGB colour.
    pub color: Vec3,
    /// Intensity: a white surface 1 m away on the axis, facing the light, is this bright.
    pub intensity: f32,
    /// Distance in metres at which the light reaches zero.
    pub range: f32,
    /// Half-angle of the full-strength cone, radians (≤ `outer_angle`).
    pub inner_angle: f32,
    /// Half-angle where the light has faded out, radians (< π/2).
    pub outer_angle: f32,
    /// Shadows (off by default).
    pub shadows: LightShadows,
}

impl SpotLight {
    /// A white spot light at `position` pointing along `direction`: intensity 1, 10 m range,
    /// cone 20° (full) to 30° (edge), no shadows.
    #[must_use]
    pub fn new(position: Vec3, direction: Vec3) -> Self {
        Self {
            position,
            direction,
            color: Vec3::ONE,
            intensity: 1.0,
            range: 10.0,
            inner_angle: 20f32.to_radians(),
            outer_angle: 30f32.to_radians(),
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

    /// Sets the cone's inner and outer half-angles, radians.
    #[must_use]
    pub fn with_cone(mut self, inner_angle: f32, outer_angle: f32) -> Self {
        self.inner_angle = inner_angle;
        self.outer_angle = outer_angle;
        self
    }

    /// Sets the shadow settings.
    #[must_use]
    pub fn with_shadows(mut self, shadows: LightShadows) -> Self {
        self.shadows = shadows;
        self
    }
}
