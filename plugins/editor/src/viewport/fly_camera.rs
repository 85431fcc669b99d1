//! [`FlyCamera`]: the editor camera's pose, flown with the mouse and keys.

use onyx_plugin_api::glam::{EulerRot, Quat, Vec3};
use onyx_plugin_api::Transform;
use serde::{Deserialize, Serialize};

/// The editor camera's pose.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FlyCamera {
    /// Position, metres.
    pub position: [f32; 3],
    /// Turn about Y, radians.
    pub yaw: f32,
    /// Tilt, radians (negative looks down).
    pub pitch: f32,
}

impl Default for FlyCamera {
    fn default() -> Self {
        Self {
            position: [0.0, 4.0, 10.0],
            yaw: 0.0,
            pitch: -0.35,
        }
    }
}

impl FlyCamera {
    fn rotation(&self) -> Quat {
        Quat::from_euler(EulerRot::YXZ, self.yaw, self.pitch, 0.0)
    }

    /// Unit direction the camera looks along.
    pub fn forward(&self) -> Vec3 {
        self.rotation() * Vec3::NEG_Z
    }

    /// The camera entity's transform.
    pub fn transform(&self) -> Transform {
        Transform::from_translation(Vec3::from_array(self.position)).with_rotation(self.rotation())
    }
}
