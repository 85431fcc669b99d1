//! [`FrameUniforms`]: the uniform block of `common.wgsl` (`struct Frame`): camera, lights,
//! shadows, sky and output settings of one frame. Positions are camera-relative.

use glam::{Mat4, Vec3};

use super::local_light_raw::LocalLightRaw;
use crate::camera::Camera;
use crate::light::{Lights, MAX_POINT_LIGHTS, MAX_SPOT_LIGHTS};
use crate::render_settings::RenderSettings;
use crate::shadow::{ShadowPlan, MAX_CASCADES, MAX_LOCAL_SHADOW_LAYERS};

/// Point and spot lights the shader loops over.
pub(crate) const MAX_LOCAL_LIGHTS: usize = MAX_POINT_LIGHTS + MAX_SPOT_LIGHTS;

/// Mirrors `struct Frame` in `shaders/common.wgsl`, field for field.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct FrameUniforms {
    view_proj: [[f32; 4]; 4],
    inv_view_proj: [[f32; 4]; 4],
    /// xyz: camera world position, w: 1 orthographic, 0 perspective.
    camera_world: [f32; 4],
    /// xyz: view direction, w: near plane.
    camera_forward: [f32; 4],
    /// rgb: ambient (sky light) scale, w: highest mip of the specular environment.
    ambient: [f32; 4],
    /// xyz: direction the sun travels, w: 1 when there is a sun.
    sun_direction: [f32; 4],
    /// rgb: sun colour × intensity, w: 1 when it casts shadows.
    sun_color: [f32; 4],
    /// x: depth bias (m), y: normal bias (texels), z: cascade count, w: filter radius (texels).
    sun_shadow: [f32; 4],
    /// View depth where each cascade ends.
    cascade_splits: [f32; 4],
    /// World size of a texel of each cascade.
    cascade_texels: [f32; 4],
    cascades: [[[f32; 4]; 4]; MAX_CASCADES],
    lights: [LocalLightRaw; MAX_LOCAL_LIGHTS],
    local_shadows: [[[f32; 4]; 4]; MAX_LOCAL_SHADOW_LAYERS],
    /// x: local lights in use, y: directional shadow-map side, z: local shadow-map side.
    counts: [u32; 4],
    /// x, y: viewport size in pixels; z, w: their reciprocals.
    viewport: [f32; 4],
    /// x: grid cell size (m), y: grid fade distance (m), z: major line every N cells.
    grid: [f32; 4],
    /// x: exposure multiplier, y: tone-mapping operator, z: 1 to encode sRGB in the shader,
    /// w: 1 to draw the sky behind the scene.
    output: [f32; 4],
    /// rgb: the procedural sky's zenith colour, w: 1 when the sky is an image (the background
    /// reads its cube).
    sky_zenith: [f32; 4],
    sky_horizon: [f32; 4],
    sky_ground: [f32; 4],
    /// xy: the camera's world x and z modulo the major grid spacing. `%` of two floats is
    /// exact, so the grid's lines are placed from a small number in the shader instead of
    /// `camera_world + hit`, which rounds to 8 mm at 100 km.
    grid_phase: [f32; 4],
}

/// What the frame uniforms are built from.
pub(crate) struct FrameInputs<'a> {
    pub(crate) camera: &'a Camera,
    pub(crate) view_proj: Mat4,
    pub(crate) lights: &'a Lights,
    pub(crate) settings: &'a RenderSettings,
    pub(crate) shadows: &'a ShadowPlan,
    pub(crate) size: (u32, u32),
    pub(crate) env_max_mip: f32,
    /// The sky's maps come from its image (the background reads the sky cube).
    pub(crate) sky_image: bool,
    pub(crate) encode_srgb: bool,
}

impl FrameUniforms {
    pub(crate) fn new(input: &FrameInputs<'_>) -> Self {
        let FrameInputs {
            camera,
            view_proj,
            lights,
            settings,
            shadows,
            size,
            env_max_mip,
            sky_image,
            encode_srgb,
        } = *input;
        let origin = camera.position;
        if lights.points.len() > MAX_POINT_LIGHTS || lights.spots.len() > MAX_SPOT_LIGHTS {
            tracing::debug!(
                points = lights.points.len(),
                spots = lights.spots.len(),
                max_points = MAX_POINT_LIGHTS,
                max_spots = MAX_SPOT_LIGHTS,
                "extra point or spot lights ignored"
            );
        }
        let mut raw_lights = [LocalLightRaw::default(); MAX_LOCAL_LIGHTS];
        let mut count = 0;
        for (i, light) in lights.points.iter().take(MAX_POINT_LIGHTS).enumerate() {
            let shadow = shadows.points.get(i).copied().flatten();
            raw_lights[count] = LocalLightRaw::point(light, origin, shadow);
            count += 1;
        }
        for (i, light) in lights.spots.iter().take(MAX_SPOT_LIGHTS).enumerate() {
            let shadow = shadows.spots.get(i).copied().flatten();
            raw_lights[count] = LocalLightRaw::spot(light, origin, shadow);
            count += 1;
        }
        let mut cascades = [[[0.0; 4]; 4]; MAX_CASCADES];
        let mut splits = [0.0; 4];
        let mut texels = [0.0; 4];
        for (i, cascade) in shadows.cascades.iter().take(MAX_CASCADES).enumerate() {
            cascades[i] = cascade.view_proj.to_cols_array_2d();
            splits[i] = cascade.split_far;
            texels[i] = cascade.texel;
        }
        let mut local_shadows = [[[0.0; 4]; 4]; MAX_LOCAL_SHADOW_LAYERS];
        for (layer, matrix) in shadows.local_matrices() {
            if let Some(slot) = local_shadows.get_mut(layer as usize) {
                *slot = matrix.to_cols_array_2d();
            }
        }
        let (sun_direction, sun_color, sun_shadow) = match &lights.sun {
            Some(sun) => (
                sun.direction.normalize_or(Vec3::NEG_Y).extend(1.0),
                (sun.color * sun.intensity).extend(if shadows.cascades.is_empty() {
                    0.0
                } else {
                    1.0
                }),
                [
                    sun.shadows.depth_bias,
                    sun.shadows.normal_bias,
                    shadows.cascades.len() as f32,
                    settings.shadow_filter_radius.max(0.0),
                ],
            ),
            None => (Vec3::NEG_Y.extend(0.0), Vec3::ZERO.extend(0.0), [0.0; 4]),
        };
        let (w, h) = (size.0.max(1) as f32, size.1.max(1) as f32);
        let ortho = if camera.projection.is_orthographic() {
            1.0
        } else {
            0.0
        };
        let sky = &settings.sky;
        Self {
            view_proj: view_proj.to_cols_array_2d(),
            inv_view_proj: view_proj.inverse().to_cols_array_2d(),
            camera_world: origin.extend(ortho).to_array(),
            camera_forward: camera.forward().extend(camera.projection.near()).to_array(),
            ambient: lights.ambient.extend(env_max_mip).to_array(),
            sun_direction: sun_direction.to_array(),
            sun_color: sun_color.to_array(),
            sun_shadow,
            cascade_splits: splits,
            cascade_texels: texels,
            cascades,
            lights: raw_lights,
            local_shadows,
            counts: [
                count as u32,
                settings.shadow_resolution,
                settings.local_shadow_resolution,
                0,
            ],
            viewport: [w, h, 1.0 / w, 1.0 / h],
            grid: [
                settings.grid_cell_size,
                settings.grid_fade_distance,
                settings.grid_major_every.max(1) as f32,
                0.0,
            ],
            output: [
                settings.exposure_ev.exp2(),
                settings.tone_mapping.shader_index() as f32,
                if encode_srgb { 1.0 } else { 0.0 },
                if settings.sky_background { 1.0 } else { 0.0 },
            ],
            sky_zenith: (sky.zenith * sky.intensity)
                .extend(if sky_image { 1.0 } else { 0.0 })
                .to_array(),
            sky_horizon: (sky.horizon * sky.intensity).extend(0.0).to_array(),
            sky_ground: (sky.ground * sky.intensity).extend(0.0).to_array(),
            grid_phase: {
                let major =
                    settings.grid_cell_size.max(1e-4) * settings.grid_major_every.max(1) as f32;
                [
                    origin.x.rem_euclid(major),
                    origin.z.rem_euclid(major),
                    0.0,
                    0.0,
                ]
            },
        }
    }
}
