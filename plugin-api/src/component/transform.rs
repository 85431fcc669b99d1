//! [`Transform`]: position, orientation and scale of an entity.

use abi_stable::StableAbi;
use glam::{Mat4, Quat, Vec3};
use serde::{Deserialize, Serialize};

/// Where an entity is: translation (metres), rotation (unit quaternion) and scale.
///
/// Plain `#[repr(C)]` data: it crosses the plugin boundary as it is. The host rejects a
/// transform with a NaN or infinite value ([`CtxError::NonFinite`](crate::CtxError)).
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Transform {
    /// Position in metres.
    #[sabi(unsafe_opaque_field)]
    pub translation: Vec3,
    /// Orientation; keep it normalized.
    #[sabi(unsafe_opaque_field)]
    pub rotation: Quat,
    /// Scale per local axis (1 = unscaled).
    #[sabi(unsafe_opaque_field)]
    pub scale: Vec3,
}

impl Default for Transform {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Transform {
    /// At the origin, unrotated, unscaled.
    pub const IDENTITY: Self = Self {
        translation: Vec3::ZERO,
        rotation: Quat::IDENTITY,
        scale: Vec3::ONE,
    };

    /// An unrotated, unscaled transform at `(x, y, z)` metres.
    pub const fn from_xyz(x: f32, y: f32, z: f32) -> Self {
        Self::from_translation(Vec3::new(x, y, z))
    }

    /// An unrotated, unscaled transform at `translation`.
    pub const fn from_translation(translation: Vec3) -> Self {
        Self {
            translation,
            ..Self::IDENTITY
        }
    }

    /// Returns this transform with `rotation`.
    #[must_use]
    pub const fn with_rotation(mut self, rotation: Quat) -> Self {
        self.rotation = rotation;
        self
    }

    /// Returns this transform with `scale`.
    #[must_use]
    pub const fn with_scale(mut self, scale: Vec3) -> Self {
        self.scale = scale;
        self
    }

    /// The local-to-world matrix.
    pub fn matrix(&self) -> Mat4 {
        Mat4::from_scale_rotation_translation(self.scale, self.rotation, self.translation)
    }

    /// Whether every component is finite (no NaN or infinity).
    pub fn is_finite(&self) -> bool {
        self.translation.is_finite() && self.rotation.is_finite() && self.scale.is_finite()
    }
}
