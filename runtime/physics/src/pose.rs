//! [`Pose`]: a rigid transform (rotation then translation).

use glam::{Quat, Vec3};

/// A rigid transform: a point `p` in local space maps to `rotation * p + translation`.
///
/// Units: metres for the translation; the rotation is a unit quaternion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    /// Translation in metres.
    pub translation: Vec3,
    /// Unit-quaternion rotation.
    pub rotation: Quat,
}

impl Default for Pose {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Pose {
    /// The identity transform.
    pub const IDENTITY: Self = Self {
        translation: Vec3::ZERO,
        rotation: Quat::IDENTITY,
    };

    /// Builds a pose from a translation and a rotation.
    #[must_use]
    pub fn new(translation: Vec3, rotation: Quat) -> Self {
        Self {
            translation,
            rotation,
        }
    }

    /// A pure translation.
    #[must_use]
    pub fn from_translation(translation: Vec3) -> Self {
        Self {
            translation,
            rotation: Quat::IDENTITY,
        }
    }

    /// Maps a local point into the parent space.
    #[inline]
    #[must_use]
    pub fn transform_point(&self, p: Vec3) -> Vec3 {
        self.rotation * p + self.translation
    }

    /// Rotates a local vector into the parent space (no translation).
    #[inline]
    #[must_use]
    pub fn transform_vector(&self, v: Vec3) -> Vec3 {
        self.rotation * v
    }

    /// Maps a parent-space point into local space.
    #[inline]
    #[must_use]
    pub fn inverse_transform_point(&self, p: Vec3) -> Vec3 {
        self.rotation.inverse() * (p - self.translation)
    }

    /// Rotates a parent-space vector into local space.
    #[inline]
    #[must_use]
    pub fn inverse_transform_vector(&self, v: Vec3) -> Vec3 {
        self.rotation.inverse() * v
    }

    /// Composition `self * other` (apply `other` first).
    #[inline]
    #[must_use]
    pub fn mul_pose(&self, other: &Pose) -> Pose {
        Pose {
            translation: self.transform_point(other.translation),
            rotation: (self.rotation * other.rotation).normalize(),
        }
    }

    /// The inverse transform.
    #[must_use]
    pub fn inverse(&self) -> Pose {
        let inv = self.rotation.inverse();
        Pose {
            translation: -(inv * self.translation),
            rotation: inv,
        }
    }

    /// `self.inverse() * other`: `other` expressed in the frame of `self`.
    ///
    /// Computed with the translation difference first, which keeps precision
    /// when both poses are far from the origin.
    #[inline]
    #[must_use]
    pub fn inv_mul(&self, other: &Pose) -> Pose {
        let inv = self.rotation.inverse();
        Pose {
            translation: inv * (other.translation - self.translation),
            rotation: (inv * other.rotation).normalize(),
        }
    }

    /// True when every component is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.translation.is_finite() && self.rotation.is_finite()
    }
}
