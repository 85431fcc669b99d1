//! [`FrameUniforms`]: the uniform block of `common.wgsl` (`struct Frame`).

use glam::{Mat4, Vec3};

use crate::camera::Camera;
use crate::light::{Lights, MAX_POINT_LIGHTS};
use crate::render_settings::RenderSettings;

/// One point light as the shader sees it.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct PointLightRaw {
    position_range: [f32; 4],
    color_intensity: [f32; 4],
}

/// Mirrors `struct Frame` in `shaders/common.wgsl`, field for field.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct FrameUniforms {
    view_proj: [[f32; 4]; 4],
    inv_view_proj: [[f32; 4]; 4],
    camera_position: [f32; 4],
    camera_forward: [f32; 4],
    ambient: [f32; 4],
    sun_direction: [f32; 4],
    sun_color: [f32; 4],
    point_lights: [PointLightRaw; MAX_POINT_LIGHTS],
    counts: [u32; 4],
    viewport: [f32; 4],
    grid: [f32; 4],
}

impl FrameUniforms {
    pub(crate) fn new(
        camera: &Camera,
        view_proj: Mat4,
        lights: &Lights,
        settings: &RenderSettings,
        size: (u32, u32),
    ) -> Self {
        let mut point_lights = [PointLightRaw::default(); MAX_POINT_LIGHTS];
        if lights.points.len() > MAX_POINT_LIGHTS {
            tracing::debug!(
                count = lights.points.len(),
                max = MAX_POINT_LIGHTS,
                "extra point lights ignored"
            );
        }
        for (raw, light) in point_lights.iter_mut().zip(&lights.points) {
            *raw = PointLightRaw {
                position_range: light.position.extend(light.range).to_array(),
                color_intensity: light.color.extend(light.intensity).to_array(),
            };
        }
        let (sun_direction, sun_color) = match &lights.sun {
            Some(sun) => (
                sun.direction.normalize_or(Vec3::NEG_Y).extend(1.0),
                (sun.color * sun.intensity).extend(0.0),
            ),
            None => (Vec3::NEG_Y.extend(0.0), Vec3::ZERO.extend(0.0)),
        };
        let (w, h) = (size.0.max(1) as f32, size.1.max(1) as f32);
        let ortho = if camera.projection.is_orthographic() {
            1.0
        } else {
            0.0
        };
        Self {
            view_proj: view_proj.to_cols_array_2d(),
            inv_view_proj: view_proj.inverse().to_cols_array_2d(),
            camera_position: camera.position().extend(ortho).to_array(),
            camera_forward: camera.forward().extend(0.0).to_array(),
            ambient: lights.ambient.extend(0.0).to_array(),
            sun_direction: sun_direction.to_array(),
            sun_color: sun_color.to_array(),
            point_lights,
            counts: [lights.points.len().min(MAX_POINT_LIGHTS) as u32, 0, 0, 0],
            viewport: [w, h, 1.0 / w, 1.0 / h],
            grid: [
                settings.grid_cell_size,
                settings.grid_fade_distance,
                settings.grid_major_every.max(1) as f32,
                0.0,
            ],
        }
    }
}
