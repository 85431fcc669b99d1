//! [`Camera`] and [`Projection`]: where the scene is seen from.
//!
//! Depth is *reversed* (1 at the near plane, falling towards 0) and a perspective camera has
//! an *infinite* far plane: floating-point depth then keeps its precision at every distance,
//! so surfaces millimetres apart do not fight even a kilometre away. The GPU sees the scene
//! *relative to the camera* ([`Camera::relative_view_projection`]): positions are made
//! camera-relative on the CPU, so a scene far from the world origin renders as sharply as one
//! at it.

use glam::{Mat4, Quat, Vec3};

/// How the camera projects the scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// Perspective projection with an infinite far plane (reverse-Z).
    Perspective {
        /// Vertical field of view in radians.
        fov_y: f32,
        /// Near plane distance in metres (> 0). Depth precision does not depend on it much
        /// (reverse-Z), but nothing nearer is drawn.
        near: f32,
        /// Objects farther than this (metres) are culled; `f32::INFINITY` culls none. The
        /// projection itself has no far plane, so this costs no depth precision.
        far: f32,
    },
    /// Orthographic projection, the box centred on the view axis (reverse-Z).
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
    /// The projection matrix for a target with this aspect ratio (width / height):
    /// reverse-Z, clip depth 1 at the near plane, 0 at infinity (perspective) or at the far
    /// plane (orthographic).
    #[must_use]
    pub fn matrix(&self, aspect: f32) -> Mat4 {
        let aspect = sane_aspect(aspect);
        match *self {
            Projection::Perspective { fov_y, near, .. } => {
                glam::camera::rh::proj::directx::perspective_infinite_reverse(
                    fov_y,
                    aspect,
                    near.max(1e-6),
                )
            }
            Projection::Orthographic { height, near, far } => {
                let half_h = height * 0.5;
                let half_w = half_h * aspect;
                // Near and far swapped: depth 1 at the near plane, 0 at the far plane.
                glam::camera::rh::proj::directx::orthographic(
                    -half_w, half_w, -half_h, half_h, far, near,
                )
            }
        }
    }

    /// A conventional projection (depth 0 near, 1 far, `far` finite or infinite) whose
    /// frustum planes cull: the same view volume as [`Projection::matrix`], ending at `far`.
    #[must_use]
    pub fn culling_matrix(&self, aspect: f32) -> Mat4 {
        let aspect = sane_aspect(aspect);
        match *self {
            Projection::Perspective { fov_y, near, far } => {
                let near = near.max(1e-6);
                if far.is_finite() && far > near {
                    glam::camera::rh::proj::directx::perspective(fov_y, aspect, near, far)
                } else {
                    glam::camera::rh::proj::directx::perspective_infinite(fov_y, aspect, near)
                }
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

    /// Near plane distance, metres.
    #[must_use]
    pub fn near(&self) -> f32 {
        match *self {
            Projection::Perspective { near, .. } | Projection::Orthographic { near, .. } => near,
        }
    }

    /// Far (culling) distance, metres.
    #[must_use]
    pub fn far(&self) -> f32 {
        match *self {
            Projection::Perspective { far, .. } | Projection::Orthographic { far, .. } => far,
        }
    }
}

fn sane_aspect(aspect: f32) -> f32 {
    if aspect.is_finite() && aspect > 0.0 {
        aspect
    } else {
        1.0
    }
}

/// A camera: a position and an orientation in the world, and a projection. Right-handed,
/// Y up, looking down its local -Z.
///
/// The position is kept as given (not recovered from a matrix inverse), so a camera far from
/// the origin is exactly where it was put. The host fills it each frame from its camera
/// entity (interpolated if it interpolates).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// World position, metres.
    pub position: Vec3,
    /// Camera-to-world rotation (unit).
    pub rotation: Quat,
    /// Projection.
    pub projection: Projection,
}

impl Camera {
    /// Default vertical field of view, 60° in radians.
    pub const DEFAULT_FOV_Y: f32 = std::f32::consts::FRAC_PI_3;
    /// Default near plane, 0.1 m.
    pub const DEFAULT_NEAR: f32 = 0.1;
    /// Default far (culling) distance, 1000 m.
    pub const DEFAULT_FAR: f32 = 1000.0;

    /// A perspective camera at `eye` looking at `target`, with +Y up; objects beyond `far`
    /// metres are culled.
    #[must_use]
    pub fn perspective_look_at(eye: Vec3, target: Vec3, fov_y: f32, near: f32, far: f32) -> Self {
        Self {
            position: eye,
            rotation: look_rotation(target - eye),
            projection: Projection::Perspective { fov_y, near, far },
        }
    }

    /// An orthographic camera at `eye` looking at `target`, showing `height` metres vertically.
    #[must_use]
    pub fn orthographic_look_at(eye: Vec3, target: Vec3, height: f32, near: f32, far: f32) -> Self {
        Self {
            position: eye,
            rotation: look_rotation(target - eye),
            projection: Projection::Orthographic { height, near, far },
        }
    }

    /// A camera from its world transform (camera-to-world, scale ignored), as an ECS stores it.
    #[must_use]
    pub fn from_world_transform(world: Mat4, projection: Projection) -> Self {
        let (_, rotation, position) = world.to_scale_rotation_translation();
        Self {
            position,
            rotation: rotation.normalize(),
            projection,
        }
    }

    /// World-to-view transform.
    #[must_use]
    pub fn view(&self) -> Mat4 {
        self.rotation_view() * Mat4::from_translation(-self.position)
    }

    /// World-to-view rotation only: the view of the camera-relative world.
    #[must_use]
    pub fn rotation_view(&self) -> Mat4 {
        Mat4::from_quat(self.rotation.inverse())
    }

    /// View-projection of the world (reverse-Z), for a target with this aspect ratio. Use it on
    /// the CPU (picking rays); the GPU gets [`Camera::relative_view_projection`].
    #[must_use]
    pub fn view_projection(&self, aspect: f32) -> Mat4 {
        self.projection.matrix(aspect) * self.view()
    }

    /// View-projection of the camera-relative world (world position minus
    /// [`Camera::position`]): what the shaders use.
    #[must_use]
    pub fn relative_view_projection(&self, aspect: f32) -> Mat4 {
        self.projection.matrix(aspect) * self.rotation_view()
    }

    /// Camera position in world space.
    #[must_use]
    pub fn position(&self) -> Vec3 {
        self.position
    }

    /// Unit direction the camera looks along, in world space.
    #[must_use]
    pub fn forward(&self) -> Vec3 {
        (self.rotation * Vec3::NEG_Z).normalize_or(Vec3::NEG_Z)
    }

    /// The world-space ray through a point of the view given in normalised device
    /// coordinates (x right, y up, both -1..1): its origin on the near plane and its unit
    /// direction. `None` for a degenerate camera.
    #[must_use]
    pub fn ray(&self, ndc_x: f32, ndc_y: f32, aspect: f32) -> Option<(Vec3, Vec3)> {
        let inverse = self.relative_view_projection(aspect).inverse();
        // Reverse-Z: depth 1 is the near plane; 0.5 is farther along the same ray.
        let near = inverse.project_point3(Vec3::new(ndc_x, ndc_y, 1.0));
        let farther = inverse.project_point3(Vec3::new(ndc_x, ndc_y, 0.5));
        let direction = (farther - near).normalize_or_zero();
        (near.is_finite() && direction != Vec3::ZERO).then(|| (near + self.position, direction))
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

/// Camera-to-world rotation looking along `forward` with +Y up; +Z up when looking straight
/// up or down.
fn look_rotation(forward: Vec3) -> Quat {
    let forward = forward.normalize_or(Vec3::NEG_Z);
    let up = if forward.cross(Vec3::Y).length_squared() < 1e-8 {
        Vec3::Z
    } else {
        Vec3::Y
    };
    let view = glam::camera::rh::view::look_to_mat4(Vec3::ZERO, forward, up);
    Quat::from_mat4(&view.inverse()).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ndc(m: Mat4, p: Vec3) -> Vec3 {
        let clip = m * p.extend(1.0);
        clip.truncate() / clip.w
    }

    #[test]
    fn perspective_maps_near_to_depth_1_and_infinity_towards_0() {
        let camera =
            Camera::perspective_look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, 1.0, 1.0, 11.0);
        let m = camera.view_projection(1.0);
        let near = ndc(m, Vec3::new(0.0, 0.0, 4.0));
        let far = ndc(m, Vec3::new(0.0, 0.0, -1.0e6));
        assert!(
            (near.z - 1.0).abs() < 1e-5 && far.z > 0.0 && far.z < 1e-5,
            "near {near}, far {far}"
        );
        // +Y world is up on screen, +X world is right when looking down -Z.
        assert!(ndc(m, Vec3::new(0.0, 1.0, 0.0)).y > 0.0);
        assert!(ndc(m, Vec3::new(1.0, 0.0, 0.0)).x > 0.0);
    }

    /// Two quads 1 mm apart seen from 1 km away with a 1 cm near plane get distinct depths
    /// (they would fight with a conventional 0.01..10 km projection).
    #[test]
    fn reverse_z_separates_a_millimetre_at_a_kilometre() {
        let camera = Camera::perspective_look_at(Vec3::ZERO, Vec3::NEG_Z, 1.0, 0.01, f32::INFINITY);
        let m = camera.view_projection(1.0);
        let a = ndc(m, Vec3::new(0.0, 0.0, -1000.0)).z;
        let b = ndc(m, Vec3::new(0.0, 0.0, -1000.001)).z;
        assert!(a > b, "nearer must be deeper-valued: {a} vs {b}");
        let ulps = a.to_bits() - b.to_bits();
        assert!(ulps >= 8, "only {ulps} float steps apart");
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
        let near = ndc(m, Vec3::new(0.0, 0.0, 4.9));
        assert!((near.z - 1.0).abs() < 1e-5, "near {near}");
        assert!(camera.projection.is_orthographic());
    }

    #[test]
    fn position_and_forward_are_kept() {
        let camera = Camera::perspective_look_at(
            Vec3::new(1.0, 2.0, 3.0),
            Vec3::new(1.0, 2.0, 0.0),
            1.0,
            0.1,
            10.0,
        );
        assert_eq!(camera.position(), Vec3::new(1.0, 2.0, 3.0));
        assert!(camera.forward().distance(Vec3::NEG_Z) < 1e-5);
        let straight_down =
            Camera::perspective_look_at(Vec3::new(0.0, 10.0, 0.0), Vec3::ZERO, 1.0, 0.1, 100.0);
        assert!(
            straight_down.view().is_finite(),
            "looking straight down must not produce NaN"
        );
        assert!(straight_down.forward().distance(Vec3::NEG_Y) < 1e-5);
    }

    #[test]
    fn relative_view_projection_matches_the_world_one() {
        let far = Vec3::new(1.0e5, 20.0, -3.0e4);
        let camera =
            Camera::perspective_look_at(far, far + Vec3::new(1.0, -0.5, -2.0), 1.0, 0.1, 100.0);
        let p = far + Vec3::new(2.0, -1.0, -4.0);
        let world = ndc(camera.view_projection(1.5), p);
        let relative = ndc(camera.relative_view_projection(1.5), p - far);
        assert!(world.distance(relative) < 1e-2, "{world} vs {relative}");
        let (origin, direction) = camera.ray(0.0, 0.0, 1.5).unwrap_or_default();
        assert!(origin.distance(far) < 0.2, "{origin}");
        assert!(direction.distance(camera.forward()) < 1e-4, "{direction}");
    }
}
