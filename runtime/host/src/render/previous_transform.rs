//! [`PreviousTransform`]: the pose at the previous fixed step, for smooth drawing.

use onyx_plugin_api::Transform;

/// The transform an entity had before the last fixed step. Drawing blends it with the current
/// one by the clock's interpolation factor, so motion computed at the fixed rate looks smooth
/// at any frame rate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PreviousTransform(pub Transform);

/// Records every drawn entity's transform before a fixed step.
pub fn snapshot(world: &mut hecs::World) {
    let mut missing = Vec::new();
    for (e, t, previous) in world
        .query_mut::<(hecs::Entity, &Transform, Option<&mut PreviousTransform>)>()
        .with::<&onyx_plugin_api::MeshRenderer>()
    {
        match previous {
            Some(p) => p.0 = *t,
            None => missing.push((e, *t)),
        }
    }
    for (e, t) in missing {
        let _ = world.insert_one(e, PreviousTransform(t));
    }
}

/// The pose to draw: `previous` blended towards `current` by `alpha` in `[0, 1]`.
pub fn interpolate(previous: &Transform, current: &Transform, alpha: f32) -> Transform {
    Transform {
        translation: previous.translation.lerp(current.translation, alpha),
        rotation: previous.rotation.slerp(current.rotation, alpha),
        scale: previous.scale.lerp(current.scale, alpha),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use onyx_plugin_api::glam::{Quat, Vec3};

    #[test]
    fn interpolation_blends_between_steps() {
        let a = Transform::from_xyz(0.0, 0.0, 0.0);
        let b = Transform::from_xyz(2.0, 0.0, 0.0).with_rotation(Quat::from_rotation_y(1.0));
        let mid = interpolate(&a, &b, 0.5);
        assert!((mid.translation - Vec3::new(1.0, 0.0, 0.0)).length() < 1e-6);
        assert!(mid.rotation.angle_between(Quat::from_rotation_y(0.5)) < 1e-5);
        assert_eq!(interpolate(&a, &b, 1.0).translation, b.translation);
    }
}
