//! [`fit_cascades`]: the directional light's shadow cascades for a camera.
//!
//! Each cascade covers one slice of the view (splits between uniform and logarithmic, see
//! `RenderSettings::shadow_cascade_lambda`). It is fitted to the slice's bounding *sphere*,
//! whose size does not change as the camera turns, and its centre is snapped to whole
//! shadow-map texels of a grid fixed in the world (laid from the frame's `anchor`, see
//! [`super::ShadowAnchor`]), so a static scene's shadows stay still while the camera moves (no
//! shimmering edges). Snapping works in f64: the camera may be far from the origin.

use glam::{DMat3, DVec3, Mat4, Vec3};

use super::CASCADE_CASTER_REACH;
use crate::camera::{Camera, Projection};
use crate::render_settings::RenderSettings;

/// One cascade: its light view-projection (camera-relative, depth 0 at the light), where it
/// ends and how big its texels are.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Cascade {
    pub(crate) view_proj: Mat4,
    /// View depth (metres along the camera's forward axis) where this cascade ends.
    pub(crate) split_far: f32,
    /// World size of one texel, metres.
    pub(crate) texel: f32,
}

/// The cascade view-projections for `camera` and a light travelling along `direction`, on the
/// texel grid laid from `anchor` (world space); count, distance, split lambda and resolution
/// from `settings`.
pub(crate) fn fit_cascades(
    camera: &Camera,
    anchor: DVec3,
    aspect: f32,
    direction: Vec3,
    settings: &RenderSettings,
) -> Vec<Cascade> {
    let count = settings.cascades();
    let distance = settings.shadow_distance;
    let lambda = settings.shadow_cascade_lambda;
    let resolution = settings.shadow_resolution;
    let direction = direction.normalize_or(Vec3::NEG_Y);
    let (near, far, ortho) = match camera.projection {
        Projection::Perspective { near, far, .. } => (near.max(1e-3), far, None),
        Projection::Orthographic {
            height, near, far, ..
        } => (near.max(0.0), far, Some(height)),
    };
    let end = distance.min(far).max(near + 1e-3);
    let lambda = lambda.clamp(0.0, 1.0);
    let resolution = resolution.max(1) as f32;
    let rotation = light_rotation(direction);
    // The camera as seen from the anchor (f64: both may be far from the world origin).
    let camera_from_anchor = camera.position.as_dvec3() - anchor;
    let mut cascades = Vec::with_capacity(count);
    let mut start = near;
    for i in 1..=count {
        let t = i as f32 / count as f32;
        let uniform = near + (end - near) * t;
        let logarithmic = near.max(1e-3) * (end / near.max(1e-3)).powf(t);
        let split = uniform + (logarithmic - uniform) * lambda;
        let (depth_center, radius) = match (camera.projection, ortho) {
            (Projection::Perspective { fov_y, .. }, _) => {
                slice_sphere(start, split, (fov_y * 0.5).tan(), aspect)
            }
            (_, Some(height)) => {
                let half_h = height * 0.5;
                let half_w = half_h * aspect;
                let half_d = (split - start) * 0.5;
                (
                    start + half_d,
                    (half_w * half_w + half_h * half_h + half_d * half_d).sqrt(),
                )
            }
            _ => (split, split),
        };
        // Round the radius up a little so floating-point noise cannot change its size.
        let radius = (radius * 16.0).ceil() / 16.0;
        let texel = 2.0 * radius / resolution;
        let center_rel = camera.forward() * depth_center;
        // Snap on the anchor's grid (light axes), in f64.
        let center_from_anchor = camera_from_anchor + center_rel.as_dvec3();
        let mut light_space = rotation * center_from_anchor;
        let step = f64::from(texel);
        light_space.x = (light_space.x / step).floor() * step;
        light_space.y = (light_space.y / step).floor() * step;
        let snapped_rel = (rotation.transpose() * light_space - camera_from_anchor).as_vec3();
        let back = radius + CASCADE_CASTER_REACH;
        let eye = snapped_rel - direction * back;
        let view = glam::camera::rh::view::look_to_mat4(eye, direction, light_up(direction));
        let projection = glam::camera::rh::proj::directx::orthographic(
            -radius,
            radius,
            -radius,
            radius,
            0.0,
            back + radius,
        );
        cascades.push(Cascade {
            view_proj: projection * view,
            split_far: split,
            texel,
        });
        start = split;
    }
    cascades
}

/// Bounding sphere of a perspective slice `near..far` (view depths) as (centre depth,
/// radius): centred on the view axis, through the near and far corners.
fn slice_sphere(near: f32, far: f32, tan_half_fov: f32, aspect: f32) -> (f32, f32) {
    let k2 = tan_half_fov * tan_half_fov * (1.0 + aspect * aspect);
    let center = ((far + near) * (1.0 + k2) * 0.5).min(far);
    let radius = ((far - center).powi(2) + far * far * k2).sqrt();
    (center, radius)
}

fn light_up(direction: Vec3) -> Vec3 {
    if direction.cross(Vec3::Y).length_squared() < 1e-6 {
        Vec3::Z
    } else {
        Vec3::Y
    }
}

/// World → light axes (x right, y up, looking down -z), f64.
fn light_rotation(direction: Vec3) -> DMat3 {
    let forward = direction.as_dvec3().normalize();
    let up = light_up(direction).as_dvec3();
    let right = forward.cross(up).normalize();
    let up = right.cross(forward);
    DMat3::from_cols(right, up, -forward).transpose()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A camera at `position`, always turned the same way (a look-at target far from the
    /// origin would lose the direction's precision).
    fn camera_at(position: Vec3) -> Camera {
        Camera {
            position,
            ..Camera::perspective_look_at(Vec3::ZERO, Vec3::new(0.3, -0.4, -1.0), 1.0, 0.1, 1000.0)
        }
    }

    /// Three cascades over 60 m, lambda 0.75, 2048 texels (the defaults).
    fn settings() -> RenderSettings {
        RenderSettings::default()
    }

    /// Cascades for `camera` on the grid laid from the world origin.
    fn fit(camera: &Camera, light: Vec3) -> Vec<Cascade> {
        fit_cascades(camera, DVec3::ZERO, 1.5, light, &settings())
    }

    /// Shadow-map texel coordinates of a world point (the fraction says where inside the
    /// texel it falls), for a 2048-texel map.
    fn texel_of(cascade: &Cascade, camera: &Camera, world: Vec3) -> (f32, f32) {
        let clip = cascade.view_proj * (world - camera.position).extend(1.0);
        (clip.x * 1024.0, clip.y * 1024.0)
    }

    /// As the camera slides, a fixed world point stays at the same place inside its texel:
    /// the cascade moves in whole texels only.
    #[test]
    fn cascades_move_in_whole_texels_as_the_camera_moves() {
        let light = Vec3::new(-0.4, -1.0, -0.3);
        let point = Vec3::new(3.3, 0.0, -7.7);
        let mut fractions = Vec::new();
        for step in 0..5 {
            let camera = camera_at(Vec3::new(0.137 * step as f32, 2.0, 0.071 * step as f32));
            let cascades = fit(&camera, light);
            let (x, y) = texel_of(&cascades[0], &camera, point);
            fractions.push((x.rem_euclid(1.0), y.rem_euclid(1.0)));
        }
        for f in &fractions {
            let (dx, dy) = ((f.0 - fractions[0].0).abs(), (f.1 - fractions[0].1).abs());
            let wrap = |d: f32| d.min(1.0 - d);
            assert!(
                wrap(dx) < 0.02 && wrap(dy) < 0.02,
                "sub-texel position moved: {fractions:?}"
            );
        }
    }

    #[test]
    fn cascades_cover_the_shadow_distance_in_growing_slices() {
        let camera = camera_at(Vec3::new(0.0, 2.0, 0.0));
        let cascades = fit(&camera, Vec3::NEG_Y);
        assert_eq!(cascades.len(), 3);
        assert!((cascades[2].split_far - 60.0).abs() < 1e-3);
        assert!(cascades[0].split_far < cascades[1].split_far);
        assert!(cascades[0].texel < cascades[1].texel && cascades[1].texel < cascades[2].texel);
        // A point 1 m in front of the camera is inside cascade 0.
        let p = camera.forward() * 1.0;
        let clip = cascades[0].view_proj * p.extend(1.0);
        assert!(
            clip.x.abs() < 1.0 && clip.y.abs() < 1.0 && (0.0..1.0).contains(&clip.z),
            "{clip}"
        );
    }

    /// On a grid laid from each camera's own start, the far-origin camera gets exactly the
    /// cascades of the one at the origin (camera-relative); on the world origin's grid they
    /// fall on other sub-texel positions.
    #[test]
    fn far_from_the_origin_the_anchored_cascades_are_the_same() {
        let light = Vec3::new(-0.4, -1.0, -0.3);
        let near_camera = camera_at(Vec3::new(0.0, 2.0, 0.0));
        let far_camera = camera_at(Vec3::new(100_000.0, 2.0, -100_000.0));
        let anchored = |camera: &Camera| {
            fit_cascades(camera, camera.position.as_dvec3(), 1.5, light, &settings())
        };
        let worst = |a: &[Cascade], b: &[Cascade]| {
            a.iter()
                .zip(b)
                .map(|(a, b)| {
                    assert_eq!(a.texel, b.texel);
                    let diff = (a.view_proj - b.view_proj).abs();
                    diff.to_cols_array().into_iter().fold(0.0f32, f32::max)
                })
                .fold(0.0f32, f32::max)
        };
        let same = worst(&anchored(&near_camera), &anchored(&far_camera));
        assert!(same < 1e-6, "anchored cascades differ by {same}");
        let world = worst(&fit(&near_camera, light), &fit(&far_camera, light));
        assert!(
            world > 1e-4,
            "on the world origin's grid the cascades should differ (sub-texel phase): {world}"
        );
    }
}
