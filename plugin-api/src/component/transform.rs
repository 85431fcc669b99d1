//! [`Transform`]: position, orientation and scale of an entity.

use abi_stable::StableAbi;
use glam::{Affine3A, Mat4, Quat, Vec3};
use serde::{Deserialize, Serialize};

use super::builtin::{finite, FileRefs, HostRefs};
use crate::{Builtin, InvalidValue};

/// Where an entity is: translation (metres), rotation (unit quaternion) and scale.
///
/// It is *local*: relative to the entity's [`Parent`](crate::Parent) when it has one, else to
/// the world. The host rejects a transform with a NaN or infinite value
/// ([`CtxError::NonFinite`](crate::CtxError)) or a zero quaternion.
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

    /// The local-to-parent matrix (local-to-world for an entity without a parent).
    pub fn matrix(&self) -> Mat4 {
        Mat4::from_scale_rotation_translation(self.scale, self.rotation, self.translation)
    }

    /// [`Transform::matrix`] as an affine transform.
    pub fn affine(&self) -> Affine3A {
        Affine3A::from_scale_rotation_translation(self.scale, self.rotation, self.translation)
    }

    /// Whether every component is finite (no NaN or infinity).
    pub fn is_finite(&self) -> bool {
        self.translation.is_finite() && self.rotation.is_finite() && self.scale.is_finite()
    }
}

/// Below this squared length a quaternion is no rotation (it cannot be normalised).
const MIN_ROTATION_LENGTH_SQUARED: f32 = 1e-12;

impl Builtin for Transform {
    const NAME: &'static str = "Transform";
    type File = Transform;

    fn tool_default() -> Option<Self> {
        Some(Transform::IDENTITY)
    }

    fn validate(&self, _refs: &dyn HostRefs) -> Result<(), InvalidValue> {
        finite("translation", &self.translation.to_array())?;
        finite("rotation", &self.rotation.to_array())?;
        finite("scale", &self.scale.to_array())?;
        let length_squared = self.rotation.length_squared();
        if length_squared < MIN_ROTATION_LENGTH_SQUARED {
            return Err(InvalidValue::invalid(
                "rotation",
                format!(
                    "must be a rotation (a unit quaternion), got one of length {}",
                    length_squared.sqrt()
                ),
            ));
        }
        Ok(())
    }

    fn to_file(&self, _refs: &dyn HostRefs) -> Transform {
        *self
    }

    fn from_file(file: Transform, _refs: &mut dyn FileRefs) -> Result<Self, InvalidValue> {
        Ok(file)
    }
}
