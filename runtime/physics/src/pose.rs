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

/// Quaternion components smaller than this are set to zero when the solver renormalises an
/// orientation ([`unit_rotation`]): a turn of ~2e-18 rad about one axis, which nothing a body
/// does in f32 can show.
pub(crate) const MIN_ROTATION_COMPONENT: f32 = 1e-18;

/// `q` normalised, with components below [`MIN_ROTATION_COMPONENT`] set to zero.
///
/// A resting body turns by rounding noise every substep, so its near-identity rotation picks
/// up components of 1e-20 and smaller, whose squares (in every normalisation and every
/// `rotation * vector` after it) are subnormal floats, a ~100-cycle microcode assist each on
/// x86. Dropping them keeps a body's orientation made of numbers the hardware handles at
/// full speed.
#[inline]
#[must_use]
pub(crate) fn unit_rotation(q: Quat) -> Quat {
    let v = glam::Vec4::from(q);
    let keep = v.abs().cmpge(glam::Vec4::splat(MIN_ROTATION_COMPONENT));
    Quat::from_vec4(glam::Vec4::select(keep, v, glam::Vec4::ZERO)).normalize()
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_rotation_drops_only_what_squares_to_a_subnormal() {
        let q = unit_rotation(Quat::from_xyzw(4.8e-12, 2.2e-24, -3.6e-12, 1.0));
        assert_eq!(q.y, 0.0);
        assert_eq!((q.x, q.z), (4.8e-12, -3.6e-12), "a real small turn is kept");
        assert!((q.length() - 1.0).abs() < 1e-6);
        let turned = Quat::from_rotation_z(0.3);
        assert!(unit_rotation(turned).abs_diff_eq(turned, 1e-7));
    }
}
