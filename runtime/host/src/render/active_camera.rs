//! [`active_camera`]: the camera the world is seen through.

use onyx_plugin_api::glam::Mat4;
use onyx_plugin_api::{Camera, Entity, Projection, Transform};

use crate::world::entity_id::to_hecs;
use crate::world::HostState;

/// The camera chosen with `Ctx::set_camera`, else the first active [`Camera`] entity, else
/// the orbit camera.
pub fn active_camera(state: &HostState) -> onyx_render::Camera {
    let world = &state.world;
    let chosen = state
        .camera_override
        .and_then(|e: Entity| to_hecs(e))
        .and_then(|e| {
            let camera = world.get::<&Camera>(e).ok()?;
            let t = world.get::<&Transform>(e).ok()?;
            Some((*camera, *t))
        })
        .or_else(|| {
            world
                .query::<(&Camera, &Transform)>()
                .iter()
                .find(|(c, _)| c.active)
                .map(|(c, t)| (*c, *t))
        });
    match chosen {
        Some((camera, t)) => {
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
            let pose = Mat4::from_rotation_translation(t.rotation, t.translation);
            onyx_render::Camera::from_world_transform(pose, projection)
        }
        None => {
            let orbit = &state.orbit;
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
