//! [`GlobalTransform`]: where an entity is in the world, all parents applied.

use glam::{Affine3A, Mat4, Quat, Vec3};

use crate::Transform;

/// An entity's world pose: its [`Transform`] composed with every ancestor's. The host computes
/// it (read it with [`Ctx::world_pose`](crate::Ctx::world_pose)); plugins write the local
/// `Transform`, or a world pose with [`Ctx::set_world_pose`](crate::Ctx::set_world_pose).
///
/// It is an affine matrix, not a translation/rotation/scale triple: a non-uniformly scaled
/// parent that is rotated shears its children, which no triple can hold.
/// [`GlobalTransform::to_transform`] gives the nearest triple (exact without shear).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GlobalTransform(pub Affine3A);

impl Default for GlobalTransform {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl From<Transform> for GlobalTransform {
    fn from(t: Transform) -> Self {
        Self(t.affine())
    }
}

impl GlobalTransform {
    /// At the origin, unrotated, unscaled.
    pub const IDENTITY: Self = Self(Affine3A::IDENTITY);

    /// The affine matrix.
    pub fn affine(&self) -> Affine3A {
        self.0
    }

    /// The 4 × 4 local-to-world matrix.
    pub fn matrix(&self) -> Mat4 {
        Mat4::from(self.0)
    }

    /// Where the entity's origin is in the world, metres.
    pub fn translation(&self) -> Vec3 {
        self.0.translation.into()
    }

    /// The world orientation (of the nearest unsheared pose).
    pub fn rotation(&self) -> Quat {
        self.to_transform().rotation
    }

    /// The nearest translation/rotation/scale triple: exact unless a rotated parent scales
    /// non-uniformly.
    pub fn to_transform(&self) -> Transform {
        let (scale, rotation, translation) = self.0.to_scale_rotation_translation();
        Transform {
            translation,
            rotation: rotation.normalize(),
            scale,
        }
    }

    /// The pose of a child at `local` under this one.
    pub fn mul_transform(&self, local: &Transform) -> Self {
        Self(self.0 * local.affine())
    }

    /// `point` (in the entity's local frame) in world coordinates.
    pub fn transform_point(&self, point: Vec3) -> Vec3 {
        self.0.transform_point3(point)
    }

    /// Whether every entry is finite.
    pub fn is_finite(&self) -> bool {
        self.0.is_finite()
    }
}
