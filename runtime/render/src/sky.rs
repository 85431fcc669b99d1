//! [`Sky`]: the environment around the scene, lighting it (image-based light) and, when
//! asked, drawn behind it.

use std::path::PathBuf;

use glam::Vec3;

/// The sky. It is rendered once into a cube map, from which the renderer prefilters the
/// specular reflections (one mip level per roughness) and the diffuse irradiance that
/// [`crate::Lights::ambient`] scales. Procedural (three colours) unless `image` names an
/// equirectangular HDR file. Change it with [`crate::Renderer::set_settings`].
#[derive(Clone, Debug, PartialEq)]
pub struct Sky {
    /// Colour straight up, linear RGB (HDR).
    pub zenith: Vec3,
    /// Colour at the horizon, linear RGB (HDR).
    pub horizon: Vec3,
    /// Colour of the ground below the horizon, linear RGB (HDR).
    pub ground: Vec3,
    /// Multiplier of all three (and of the image).
    pub intensity: f32,
    /// An equirectangular HDR image (Radiance `.hdr`, linear radiance; its top row straight up,
    /// its centre looking down −Z) used instead of the three colours. One that cannot be read
    /// is logged as a warning and the procedural sky is used. `None` by default.
    pub image: Option<PathBuf>,
}

impl Default for Sky {
    /// A clear day: deep blue above, pale at the horizon, a warm grey ground.
    fn default() -> Self {
        Self {
            zenith: Vec3::new(0.20, 0.38, 0.80),
            horizon: Vec3::new(0.78, 0.85, 0.95),
            ground: Vec3::new(0.32, 0.30, 0.28),
            intensity: 1.0,
            image: None,
        }
    }
}

impl Sky {
    /// The default sky's colours, lighting with the equirectangular HDR image at `path`.
    #[must_use]
    pub fn image(path: impl Into<PathBuf>) -> Self {
        Self {
            image: Some(path.into()),
            ..Self::default()
        }
    }

    /// A sky of one colour everywhere (a furnace: handy for tests of energy conservation).
    #[must_use]
    pub fn uniform(color: Vec3) -> Self {
        Self {
            zenith: color,
            horizon: color,
            ground: color,
            intensity: 1.0,
            image: None,
        }
    }

    /// The sky's radiance in direction `dir` (unit, world space): the same function
    /// `environment.wgsl` renders.
    #[must_use]
    pub fn radiance(&self, dir: Vec3) -> Vec3 {
        let y = dir.y.clamp(-1.0, 1.0);
        let color = if y >= 0.0 {
            let t = y.powf(0.5);
            self.horizon.lerp(self.zenith, t)
        } else {
            let t = (-y * 4.0).min(1.0);
            self.horizon.lerp(self.ground, t)
        };
        color * self.intensity
    }
}
