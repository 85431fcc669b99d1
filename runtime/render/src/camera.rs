//! [`Camera`] and [`Projection`]: where the scene is seen from.

use glam::{Mat4, Vec3};

/// How the camera projects the scene. Depth maps to 0..1 (wgpu's clip space).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// Perspective projection.
    Perspective {
        /// Vertical field of view in radians.
        fov_y: f32,
        /// Near plane distance in metres (> 0).
        near: f32,
        /// Far plane distance in metres (> near).
        far: f32,
    },
    /// Orthographic projection, the box centred on the view axis.
    Orthographic {
        /// Height of the visible box in metres; the width follows the aspect ratio.
        height: f32,
        /// Near plane distance in metres (may be negative).
        near: f32,
        /// Far plane distance in metres (> near).
        far: f32,
    },
}

impl Projection {
    /// The projection matrix for a target with this aspect ratio (width / height).
    #[must_use]
    pub fn matrix(&self, aspect: f32) -> Mat4 {
        let aspect = if aspect.is_finite() && aspect > 0.0 {
            aspect
        } else {
            1.0
        };
        match *self {
            Projection::Perspective { fov_y, near, far } => {
                glam::camera::rh::proj::directx::perspective(fov_y, aspect, near, far)
            }
            Projection::Orthographic { height, near, far } => {
                let half_h = height * 0.5;
                let half_w = half_h * aspect;
                glam::camera::rh::proj::directx::orthographic(
                    -half_w, half_w, -half_h, half_h, near, far,
                )
            }
        }
    }

    /// Whether this is an orthographic projection.
    #[must_use]
    pub fn is_orthographic(&self) -> bool {
        matches!(self, Projection::Orthographic { .. })
    }
}

/// A camera: a world-to-view transform and a projection. Right-handed, Y up, looking down -Z
/// in view space.
///
/// The host fills it each frame from its camera entity (interpolated if it interpolates).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// World-to-view transform (the inverse of the camera's world transform).
    pub view: Mat4,
    /// Projection.
    pub projection: Projection,
}

impl Camera {
    /// Default vertical field of view, 60° in radians.
    pub const DEFAULT_FOV_Y: f32 = std::f32::consts::FRAC_PI_3;
    /// Default near plane, 0.1 m.
    pub const DEFAULT_NEAR: f32 = 0.1;
    /// Default far plane, 1000 m.
    pub const DEFAULT_FAR: f32 = 1000.0;

    /// A perspective camera at `eye` looking at `target`, with +Y up.
    #[must_use]
    pub fn perspective_look_at(eye: Vec3, target: Vec3, fov_y: f32, near: f32, far: f32) -> Self {
        Self {
            view: look_at(eye, target),
            projection: Projection::Perspective { fov_y, near, far },
        }
    }

    /// An orthographic camera at `eye` looking at `target`, showing `height` metres vertically.
    #[must_use]
    pub fn orthographic_look_at(eye: Vec3, target: Vec3, height: f32, near: f32, far: f32) -> Self {
        Self {
            view: look_at(eye, target),
            projection: Projection::Orthographic { height, near, far },
        }
    }

    /// A camera from its world transform (camera-to-world), as an ECS stores it.
    #[must_use]
    pub fn from_world_transform(world: Mat4, projection: Projection) -> Self {
        Self {
            view: world.inverse(),
            projection,
        }
    }

    /// View-projection matrix for a target with this aspect ratio (width / height).
    #[must_use]
    pub fn view_projection(&self, aspect: f32) -> Mat4 {
        self.projection.matrix(aspect) * self.view
    }

    /// Camera position in world space.
    #[must_use]
    pub fn position(&self) -> Vec3 {
        self.view.inverse().w_axis.truncate()
    }

    /// Unit direction the camera looks along, in world space.
    #[must_use]
    pub fn forward(&self) -> Vec3 {
        (-self.view.inverse().z_axis.truncate()).normalize_or(Vec3::NEG_Z)
    }
}

impl Default for Camera {
    /// A perspective camera at (0, 2, 5) looking at the origin.
    fn default() -> Self {
        Self::perspective_look_at(
            Vec3::new(0.0, 2.0, 5.0),
            Vec3::ZERO,
            Self::DEFAULT_FOV_Y,
            Self::DEFAULT_NEAR,
            Self::DEFAULT_FAR,
        )
    }
}

/// Right-handed look-at with +Y up; falls back to +Z up when looking straight up or down.
fn look_at(eye: Vec3, target: Vec3) -> Mat4 {
    let forward = (target - eye).normalize_or(Vec3::NEG_Z);
    let up = if forward.cross(Vec3::Y).length_squared() < 1e-8 {
        Vec3::Z
    } else {
        Vec3::Y
    };
    glam::camera::rh::view::look_at_mat4(eye, target, up)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ndc(m: Mat4, p: Vec3) -> Vec3 {
        let clip = m * p.extend(1.0);
        clip.truncate() / clip.w
    }

    #[test]
    fn perspective_maps_near_to_depth_0_and_far_to_1() {
        let camera =
            Camera::perspective_look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, 1.0, 1.0, 11.0);
        let m = camera.view_projection(1.0);
        let near = ndc(m, Vec3::new(0.0, 0.0, 4.0));
        let far = ndc(m, Vec3::new(0.0, 0.0, -6.0));
        assert!(
            near.z.abs() < 1e-5 && (far.z - 1.0).abs() < 1e-5,
            "near {near}, far {far}"
        );
        // +Y world is up on screen, +X world is right when looking down -Z.
        assert!(ndc(m, Vec3::new(0.0, 1.0, 0.0)).y > 0.0);
        assert!(ndc(m, Vec3::new(1.0, 0.0, 0.0)).x > 0.0);
    }

    #[test]
    fn orthographic_shows_the_requested_height() {
        let camera =
            Camera::orthographic_look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, 4.0, 0.1, 10.0);
        let m = camera.view_projection(2.0);
        let top = ndc(m, Vec3::new(0.0, 2.0, 0.0));
        let right = ndc(m, Vec3::new(4.0, 0.0, 0.0));
        assert!(
            (top.y - 1.0).abs() < 1e-5 && (right.x - 1.0).abs() < 1e-5,
            "top {top}, right {right}"
        );
        assert!(camera.projection.is_orthographic());
    }

    #[test]
    fn position_and_forward_come_back_from_the_view() {
        let camera = Camera::perspective_look_at(
            Vec3::new(1.0, 2.0, 3.0),
            Vec3::new(1.0, 2.0, 0.0),
            1.0,
            0.1,
            10.0,
        );
        assert!(camera.position().distance(Vec3::new(1.0, 2.0, 3.0)) < 1e-5);
        assert!(camera.forward().distance(Vec3::NEG_Z) < 1e-5);
        let straight_down =
            Camera::perspective_look_at(Vec3::new(0.0, 10.0, 0.0), Vec3::ZERO, 1.0, 0.1, 100.0);
        assert!(
            straight_down.view.is_finite(),
            "looking straight down must not produce NaN"
        );
    }
}
