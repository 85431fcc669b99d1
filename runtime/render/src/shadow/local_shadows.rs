//! The shadow views of spot lights (one perspective view along the cone) and point lights
//! (six cube faces, each a little wider than 90° so the filter never reads past a face's
//! edge).

use glam::{Mat4, Vec3};

/// The near plane of local shadow views: a fraction of the light's range, at least 2 cm.
pub(crate) fn local_near(range: f32) -> f32 {
    (range * 0.002).max(0.02).min(range * 0.5)
}

/// The view-projection (camera-relative) of a spot light at `position` (relative) pointing
/// along `direction`, covering its outer cone; and the field of view used.
pub(crate) fn spot_view(
    position: Vec3,
    direction: Vec3,
    outer_angle: f32,
    range: f32,
) -> (Mat4, f32) {
    let direction = direction.normalize_or(Vec3::NEG_Z);
    let fov = (outer_angle * 2.0 + 4f32.to_radians()).clamp(5f32.to_radians(), 175f32.to_radians());
    let up = if direction.cross(Vec3::Y).length_squared() < 1e-6 {
        Vec3::Z
    } else {
        Vec3::Y
    };
    let view = glam::camera::rh::view::look_to_mat4(position, direction, up);
    let projection =
        glam::camera::rh::proj::directx::perspective(fov, 1.0, local_near(range), range.max(0.05));
    (projection * view, fov)
}

/// Directions of the six cube faces, in the order the shader picks them by major axis:
/// +X, -X, +Y, -Y, +Z, -Z.
pub(crate) const CUBE_FACES: [(Vec3, Vec3); 6] = [
    (Vec3::X, Vec3::Y),
    (Vec3::NEG_X, Vec3::Y),
    (Vec3::Y, Vec3::Z),
    (Vec3::NEG_Y, Vec3::Z),
    (Vec3::Z, Vec3::Y),
    (Vec3::NEG_Z, Vec3::Y),
];

/// The six face view-projections of a point light at `position` (relative), and the field of
/// view of each (90° plus a margin of `margin_texels` at `resolution`).
pub(crate) fn point_views(
    position: Vec3,
    range: f32,
    resolution: u32,
    margin_texels: f32,
) -> ([Mat4; 6], f32) {
    let half_tan = 1.0 + 2.0 * margin_texels / resolution.max(1) as f32;
    let fov = 2.0 * half_tan.atan();
    let projection =
        glam::camera::rh::proj::directx::perspective(fov, 1.0, local_near(range), range.max(0.05));
    let views = CUBE_FACES.map(|(forward, up)| {
        projection * glam::camera::rh::view::look_to_mat4(position, forward, up)
    });
    (views, fov)
}
