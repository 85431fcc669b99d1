//! [`Camera`]: a view into the scene from the entity's transform.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

/// The projection of a [`Camera`].
#[repr(C, u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Projection {
    /// Perspective, with a vertical field of view in radians.
    Perspective {
        /// Vertical field of view, radians.
        fov_y: f32,
    },
    /// Orthographic, showing `height` metres vertically.
    Orthographic {
        /// Visible height, metres.
        height: f32,
    },
}

/// A camera looking down its entity's local -Z, with Y up. The host draws through the camera
/// chosen with [`Ctx::set_camera`](crate::Ctx::set_camera), else the first `active` one, else
/// its own orbit camera.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Camera {
    /// Perspective or orthographic.
    pub projection: Projection,
    /// Near plane, metres (> 0).
    pub near: f32,
    /// Far plane, metres (> near).
    pub far: f32,
    /// Whether the host may draw through it.
    pub active: bool,
}

impl Camera {
    /// An active perspective camera with a `fov_y`-radian vertical field of view, 0.1..1000 m.
    pub const fn perspective(fov_y: f32) -> Self {
        Self {
            projection: Projection::Perspective { fov_y },
            near: 0.1,
            far: 1000.0,
            active: true,
        }
    }

    /// An active orthographic camera showing `height` metres vertically, 0.1..1000 m.
    pub const fn orthographic(height: f32) -> Self {
        Self {
            projection: Projection::Orthographic { height },
            near: 0.1,
            far: 1000.0,
            active: true,
        }
    }
}
