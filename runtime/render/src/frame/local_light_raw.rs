//! [`LocalLightRaw`]: one point or spot light as the shader sees it (`LocalLight` in
//! `common.wgsl`): both kinds share the layout, a spot adds its direction and cone.

use glam::Vec3;

use crate::light::{LightShadows, PointLight, SpotLight};
use crate::shadow::LocalShadow;

/// `color_kind.w` of a point light.
const POINT: f32 = 0.0;
/// `color_kind.w` of a spot light.
const SPOT: f32 = 1.0;

/// One point or spot light (camera-relative).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct LocalLightRaw {
    /// xyz: camera-relative position, w: range (m).
    position_range: [f32; 4],
    /// rgb: colour × intensity, w: 0 point, 1 spot.
    color_kind: [f32; 4],
    /// xyz: spot direction (unit), w: cos of the outer angle.
    direction_cos: [f32; 4],
    /// x: 1 / (cos inner − cos outer), y: first shadow layer (−1: none), z: depth bias (m),
    /// w: normal bias (texels).
    cone_shadow: [f32; 4],
    /// x: shadow near, y: shadow far, z: texel size one metre away, w: unused.
    shadow_range: [f32; 4],
}

/// What a point and a spot light have in common.
struct Common<'a> {
    position: Vec3,
    range: f32,
    radiance: Vec3,
    settings: &'a LightShadows,
    shadow: Option<LocalShadow>,
}

impl LocalLightRaw {
    /// A point light seen from `origin`, with its shadow if it casts one this frame.
    pub(crate) fn point(light: &PointLight, origin: Vec3, shadow: Option<LocalShadow>) -> Self {
        // A point light has no cone: cos −2 is below every angle's.
        Self::new(
            &Common {
                position: light.position - origin,
                range: light.range,
                radiance: light.color * light.intensity,
                settings: &light.shadows,
                shadow,
            },
            POINT,
            [0.0, -1.0, 0.0, -2.0],
            0.0,
        )
    }

    /// A spot light seen from `origin`, with its shadow if it casts one this frame.
    pub(crate) fn spot(light: &SpotLight, origin: Vec3, shadow: Option<LocalShadow>) -> Self {
        let outer = light
            .outer_angle
            .clamp(1e-3, std::f32::consts::FRAC_PI_2 - 1e-3);
        let inner = light.inner_angle.clamp(0.0, outer);
        let (cos_outer, cos_inner) = (outer.cos(), inner.cos());
        Self::new(
            &Common {
                position: light.position - origin,
                range: light.range,
                radiance: light.color * light.intensity,
                settings: &light.shadows,
                shadow,
            },
            SPOT,
            light
                .direction
                .normalize_or(Vec3::NEG_Z)
                .extend(cos_outer)
                .to_array(),
            1.0 / (cos_inner - cos_outer).max(1e-4),
        )
    }

    fn new(common: &Common<'_>, kind: f32, direction_cos: [f32; 4], cone_scale: f32) -> Self {
        let shadow = common.shadow;
        Self {
            position_range: common.position.extend(common.range.max(1e-4)).to_array(),
            color_kind: common.radiance.extend(kind).to_array(),
            direction_cos,
            cone_shadow: [
                cone_scale,
                shadow.map_or(-1.0, |s| s.layer as f32),
                common.settings.depth_bias,
                common.settings.normal_bias,
            ],
            shadow_range: shadow.map_or([0.0; 4], |s| [s.near, s.far, s.texel_per_metre, 0.0]),
        }
    }
}
