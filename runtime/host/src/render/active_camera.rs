//! [`active_camera`]: the camera the world is seen through.

use onyx_plugin_api::glam::Mat4;
use onyx_plugin_api::{Camera, Entity, GlobalTransform, Projection};

use super::ViewState;
use crate::world::WorldState;

/// The camera chosen with `Ctx::set_camera`, else the first active [`Camera`] entity, else
/// the orbit camera. A camera looks from its world pose (a camera on a rig moves with it;
/// scale does not apply).
pub fn active_camera(world: &WorldState, view: &ViewState) -> onyx_render::Camera {
    let ecs = &world.ecs;
    let chosen = view
        .camera_override
        .and_then(|e: Entity| world.entity(e))
        .and_then(|e| Some((*ecs.get::<&Camera>(e).ok()?, e)))
        .or_else(|| {
            ecs.query::<(hecs::Entity, &Camera)>()
                .with::<&onyx_plugin_api::Transform>()
                .iter()
                .filter(|(_, c)| c.active)
                .min_by_key(|(e, _)| e.to_bits())
                .map(|(e, c)| (*c, e))
        })
        .filter(|(_, e)| ecs.satisfies::<&onyx_plugin_api::Transform>(*e));
    match chosen {
        Some((camera, e)) => {
            let projection = match camera.projection {
                Projection::Perspective { fov_y } => onyx_render::Projection::Perspective {
                    fov_y,
                    near: camera.near,
                    far: camera.far,
                },
                Projection::Orthographic { height } => onyx_render::Projection::Orthographic {
                    height,
                    near: camera.near,
                    far: camera.far,
                },
            };
            let pose = GlobalTransform(world.world_pose(e)).to_transform();
            let pose = Mat4::from_rotation_translation(pose.rotation, pose.translation);
            onyx_render::Camera::from_world_transform(pose, projection)
        }
        None => {
            let orbit = &view.orbit;
            onyx_render::Camera::perspective_look_at(
                orbit.eye(),
                orbit.target,
                50f32.to_radians(),
                0.1,
                1000.0,
            )
        }
    }
}
