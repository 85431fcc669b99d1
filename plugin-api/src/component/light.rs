//! [`Light`]: ambient, directional ("sun") and point lights.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

use super::builtin::{finite, FileRefs, HostRefs};
use crate::{Builtin, InvalidValue};

/// A light. Directional lights shine along their entity's local -Z; point lights sit at the
/// entity's position. The renderer uses the first ambient and directional light it finds and
/// up to 8 point lights. Colours are linear RGB.
#[repr(C, u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Light {
    /// Light from everywhere, added to every lit surface.
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
        /// Multiplier.
        intensity: f32,
    },
    /// A light at a point, fading to nothing at `range` metres.
    Point {
        /// Colour.
        color: [f32; 3],
        /// Multiplier.
        intensity: f32,
        /// Reach, metres.
        range: f32,
    },
}

impl Light {
    /// A white point light of intensity 1 reaching `range` metres.
    pub const fn point(range: f32) -> Self {
        Light::Point {
            color: [1.0, 1.0, 1.0],
            intensity: 1.0,
            range,
        }
    }

    /// A white sun of intensity 1.
    pub const fn sun() -> Self {
        Light::Directional {
            color: [1.0, 1.0, 1.0],
            intensity: 1.0,
        }
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
            Light::Ambient { color, intensity } | Light::Directional { color, intensity } => {
                finite("color", &color)?;
                finite("intensity", &[intensity])
            }
            Light::Point {
                color,
                intensity,
                range,
            } => {
                finite("color", &color)?;
                finite("intensity", &[intensity])?;
                finite("range", &[range])
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
