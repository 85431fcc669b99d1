//! [`PreviousPose`]: the world pose at the previous fixed step, for smooth drawing.

use onyx_plugin_api::glam::Affine3A;
use onyx_plugin_api::{MeshRenderer, Transform};

use crate::world::WorldState;

/// Largest difference between a world pose and its translation/rotation/scale triple
/// recomposed, relative to the pose's size, for the triple to stand for the pose (above it
/// the pose is sheared: a non-uniform scale under a rotated parent).
const UNSHEARED_TOLERANCE: f32 = 1e-4;

/// The world pose a drawn entity had before the last fixed step. Drawing blends it with the
/// current one by the clock's interpolation factor, so motion computed at the fixed rate —
/// the entity's own or its parents' — looks smooth at any frame rate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PreviousPose(pub Affine3A);

/// Records every drawn entity's world pose before a fixed step (the scene graph's world
/// poses must be up to date).
pub fn snapshot(world: &mut WorldState) {
    let WorldState { ecs, hierarchy, .. } = world;
    let mut missing = Vec::new();
    for (e, t, previous) in ecs
        .query_mut::<(hecs::Entity, &Transform, Option<&mut PreviousPose>)>()
        .with::<&MeshRenderer>()
    {
        let pose = hierarchy.world_of(e, t);
        match previous {
            Some(p) => p.0 = pose,
            None => missing.push((e, pose)),
        }
    }
    for (e, pose) in missing {
        let _ = ecs.insert_one(e, PreviousPose(pose));
    }
}

/// The pose to draw: `previous` blended towards `current` by `alpha` in `[0, 1]` —
/// translation and scale linearly, rotation along the shortest arc. A sheared pose has no
/// rotation to blend: its matrix is blended entry by entry.
pub fn interpolate(previous: &Affine3A, current: &Affine3A, alpha: f32) -> Affine3A {
    if previous == current {
        return *current;
    }
    match (unsheared(previous), unsheared(current)) {
        (Some(a), Some(b)) => Affine3A::from_scale_rotation_translation(
            a.scale.lerp(b.scale, alpha),
            a.rotation.slerp(b.rotation, alpha),
            a.translation.lerp(b.translation, alpha),
        ),
        _ => Affine3A {
            matrix3: previous.matrix3 * (1.0 - alpha) + current.matrix3 * alpha,
            translation: previous.translation.lerp(current.translation, alpha),
        },
    }
}

/// The translation/rotation/scale triple of `pose`, if it holds the pose exactly.
fn unsheared(pose: &Affine3A) -> Option<Transform> {
    let (scale, rotation, translation) = pose.to_scale_rotation_translation();
    let rotation = rotation.normalize();
    let back = Affine3A::from_scale_rotation_translation(scale, rotation, translation);
    let size = pose
        .matrix3
        .abs()
        .to_cols_array()
        .into_iter()
        .fold(0.0f32, f32::max);
    let error = (back.matrix3 - pose.matrix3)
        .abs()
        .to_cols_array()
        .into_iter()
        .fold(0.0f32, f32::max);
    (error <= UNSHEARED_TOLERANCE * size.max(1e-6) && rotation.is_finite()).then_some(Transform {
        translation,
        rotation,
        scale,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use onyx_plugin_api::glam::{Mat3A, Quat, Vec3};

    #[test]
    fn interpolation_blends_between_steps() {
        let a = Affine3A::IDENTITY;
        let b = Affine3A::from_rotation_translation(
            Quat::from_rotation_y(1.0),
            Vec3::new(2.0, 0.0, 0.0),
        );
        let mid = interpolate(&a, &b, 0.5);
        assert!((Vec3::from(mid.translation) - Vec3::new(1.0, 0.0, 0.0)).length() < 1e-6);
        let (_, rotation, _) = mid.to_scale_rotation_translation();
        assert!(rotation.angle_between(Quat::from_rotation_y(0.5)) < 1e-5);
        assert_eq!(interpolate(&a, &b, 1.0).translation, b.translation);
    }

    #[test]
    fn a_sheared_pose_is_blended_entry_by_entry_and_lands_on_both_ends() {
        let shear = Affine3A {
            matrix3: Mat3A::from_cols_array(&[1.0, 0.0, 0.0, 0.5, 1.0, 0.0, 0.0, 0.0, 1.0]),
            translation: Vec3::ZERO.into(),
        };
        assert!(unsheared(&shear).is_none());
        let moved = Affine3A {
            translation: Vec3::new(0.0, 2.0, 0.0).into(),
            ..shear
        };
        assert_eq!(interpolate(&shear, &moved, 0.0), shear);
        assert_eq!(interpolate(&shear, &moved, 1.0), moved);
        assert_eq!(interpolate(&shear, &moved, 0.5).translation.y, 1.0);
    }
}
