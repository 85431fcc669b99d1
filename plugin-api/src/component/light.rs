//! [`Light`]: ambient, directional ("sun"), point and spot lights.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

use super::builtin::{finite, FileRefs, HostRefs};
use crate::{Builtin, InvalidValue};

/// A light. Directional and spot lights shine along their entity's local -Z; point and spot
/// lights sit at the entity's position; an ambient light needs no position (nor a
/// [`Transform`](crate::Transform)). The renderer uses the first directional light it finds,
/// every ambient light (added up) and up to 8 point and 8 spot lights. Colours are linear RGB.
///
/// Shadows: on by default for directional lights (a scene gets shadows without asking), off
/// for point and spot lights (each costs six or one extra passes a frame; the renderer draws
/// a bounded number of them).
#[repr(C, u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Light {
    /// The sky's light from everywhere (image-based: diffuse and reflections), scaled by
    /// colour × intensity.
    Ambient {
        /// Colour.
        color: [f32; 3],
        /// Multiplier.
        intensity: f32,
    },
    /// A light infinitely far away.
    Directional {
        /// Colour.
        color: [f32; 3],
        /// Multiplier: a white surface facing the light is this bright.
        intensity: f32,
        /// Whether it casts shadows (cascaded shadow maps). Default true.
        #[serde(default = "yes", skip_serializing_if = "is_true")]
        shadows: bool,
    },
    /// A light at a point, inverse-square falloff fading to nothing at `range` metres.
    Point {
        /// Colour.
        color: [f32; 3],
        /// Multiplier: a white surface 1 m away facing the light is this bright.
        intensity: f32,
        /// Reach, metres.
        range: f32,
        /// Whether it casts shadows (a cube shadow map). Default false.
        #[serde(default, skip_serializing_if = "is_false")]
        shadows: bool,
    },
    /// A light at a point shining inside a cone around its local -Z.
    Spot {
        /// Colour.
        color: [f32; 3],
        /// Multiplier: a white surface 1 m away on the axis, facing the light, is this bright.
        intensity: f32,
        /// Reach, metres.
        range: f32,
        /// Half-angle of the full-strength cone, radians.
        inner_angle: f32,
        /// Half-angle where the light has faded out, radians (> `inner_angle`, < π/2).
        outer_angle: f32,
        /// Whether it casts shadows (one shadow map). Default false.
        #[serde(default, skip_serializing_if = "is_false")]
        shadows: bool,
    },
}

fn yes() -> bool {
    true
}

fn is_true(b: &bool) -> bool {
    *b
}

fn is_false(b: &bool) -> bool {
    !*b
}

impl Light {
    /// A white point light of intensity 1 reaching `range` metres, without shadows.
    pub const fn point(range: f32) -> Self {
        Light::Point {
            color: [1.0, 1.0, 1.0],
            intensity: 1.0,
            range,
            shadows: false,
        }
    }

    /// A white sun of intensity 1, casting shadows.
    pub const fn sun() -> Self {
        Light::Directional {
            color: [1.0, 1.0, 1.0],
            intensity: 1.0,
            shadows: true,
        }
    }

    /// A white spot light of intensity 1 reaching `range` metres, cone 20° (full) to 30°
    /// (edge), without shadows.
    pub const fn spot(range: f32) -> Self {
        Light::Spot {
            color: [1.0, 1.0, 1.0],
            intensity: 1.0,
            range,
            inner_angle: 20.0 * std::f32::consts::PI / 180.0,
            outer_angle: 30.0 * std::f32::consts::PI / 180.0,
            shadows: false,
        }
    }

    /// Returns this light with shadows on or off (ambient lights cast none).
    #[must_use]
    pub const fn with_shadows(mut self, on: bool) -> Self {
        match &mut self {
            Light::Ambient { .. } => {}
            Light::Directional { shadows, .. }
            | Light::Point { shadows, .. }
            | Light::Spot { shadows, .. } => *shadows = on,
        }
        self
    }
}

impl Builtin for Light {
    const NAME: &'static str = "Light";
    type File = Light;

    fn tool_default() -> Option<Self> {
        Some(Light::sun())
    }

    fn validate(&self, _refs: &dyn HostRefs) -> Result<(), InvalidValue> {
        match *self {
            Light::Ambient { color, intensity }
            | Light::Directional {
                color, intensity, ..
            } => {
                finite("color", &color)?;
                finite("intensity", &[intensity])
            }
            Light::Point {
                color,
                intensity,
                range,
                ..
            } => {
                finite("color", &color)?;
                finite("intensity", &[intensity])?;
                finite("range", &[range])
            }
            Light::Spot {
                color,
                intensity,
                range,
                inner_angle,
                outer_angle,
                ..
            } => {
                finite("color", &color)?;
                finite("intensity", &[intensity])?;
                finite("range", &[range])?;
                finite("inner_angle", &[inner_angle])?;
                finite("outer_angle", &[outer_angle])?;
                if !(0.0..std::f32::consts::FRAC_PI_2).contains(&outer_angle) {
                    return Err(InvalidValue::invalid(
                        "outer_angle",
                        format!("is {outer_angle} rad, outside 0..π/2"),
                    ));
                }
                if !(0.0..=outer_angle).contains(&inner_angle) {
                    return Err(InvalidValue::invalid(
                        "inner_angle",
                        format!("is {inner_angle} rad, outside 0..=outer_angle ({outer_angle})"),
                    ));
                }
                Ok(())
            }
        }
    }

    fn to_file(&self, _refs: &dyn HostRefs) -> Light {
        *self
    }

    fn from_file(file: Light, _refs: &mut dyn FileRefs) -> Result<Self, InvalidValue> {
        Ok(file)
    }
}
