//! [`Camera`]: a view into the scene from the entity's transform.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

use super::builtin::{finite, FileRefs, HostRefs};
use crate::{Builtin, InvalidValue};

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

impl Builtin for Camera {
    const NAME: &'static str = "Camera";
    type File = Camera;

    fn tool_default() -> Option<Self> {
        Some(Camera::perspective(60f32.to_radians()))
    }

    fn validate(&self, _refs: &dyn HostRefs) -> Result<(), InvalidValue> {
        let (field, extent) = match self.projection {
            Projection::Perspective { fov_y } => ("projection.fov_y", fov_y),
            Projection::Orthographic { height } => ("projection.height", height),
        };
        finite("near", &[self.near])?;
        finite("far", &[self.far])?;
        finite(field, &[extent])?;
        if self.near <= 0.0 {
            return Err(InvalidValue::invalid(
                "near",
                format!("must be > 0 m, got {}", self.near),
            ));
        }
        if self.far <= self.near {
            return Err(InvalidValue::invalid(
                "far",
                format!("must be > near ({} m), got {}", self.near, self.far),
            ));
        }
        if extent <= 0.0 {
            return Err(InvalidValue::invalid(
                field,
                format!("must be > 0, got {extent}"),
            ));
        }
        Ok(())
    }

    fn to_file(&self, _refs: &dyn HostRefs) -> Camera {
        *self
    }

    fn from_file(file: Camera, _refs: &mut dyn FileRefs) -> Result<Self, InvalidValue> {
        Ok(file)
    }
}
