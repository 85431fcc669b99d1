//! [`ShadowPlan`]: every shadow view of one frame — the directional light's cascades, then
//! the views of the first shadowed spot and point lights — and where each is drawn.

use glam::{DVec3, Mat4};

use super::cascades::{fit_cascades, Cascade};
use super::local_shadows::{local_near, point_views, spot_view};
use super::MAX_LOCAL_SHADOW_LAYERS;
use crate::camera::Camera;
use crate::frustum::Frustum;
use crate::light::{Lights, MAX_POINT_LIGHTS, MAX_SPOT_LIGHTS};
use crate::render_settings::RenderSettings;

/// Which layer of which shadow texture a view draws into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ShadowTarget {
    /// Layer of the directional array.
    Cascade(u32),
    /// Layer of the local (spot and point) array.
    Local(u32),
}

/// One shadow pass: its camera-relative view-projection (depth 0 nearest the light) and
/// target.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ShadowView {
    pub(crate) view_proj: Mat4,
    pub(crate) target: ShadowTarget,
}

/// A local light's shadow as the shader reads it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct LocalShadow {
    /// First layer (six consecutive ones for a point light).
    pub(crate) layer: u32,
    pub(crate) near: f32,
    pub(crate) far: f32,
    /// World size of a texel one metre from the light.
    pub(crate) texel_per_metre: f32,
}

/// The frame's shadow views.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct ShadowPlan {
    pub(crate) views: Vec<ShadowView>,
    /// Each view's volume, for culling casters (same order as `views`).
    pub(crate) frusta: Vec<Frustum>,
    /// The directional cascades (empty when the sun casts no shadow).
    pub(crate) cascades: Vec<Cascade>,
    /// Per spot light (in use order), its shadow if it casts one.
    pub(crate) spots: Vec<Option<LocalShadow>>,
    /// Per point light (in use order), its shadow if it casts one.
    pub(crate) points: Vec<Option<LocalShadow>>,
    /// Local layers used.
    pub(crate) local_layers: u32,
}

impl ShadowPlan {
    /// The shadow views for `lights` seen by `camera` on a target of `aspect`, the cascades
    /// snapped on the texel grid laid from `anchor` (see [`super::ShadowAnchor`]).
    pub(crate) fn new(
        camera: &Camera,
        anchor: DVec3,
        aspect: f32,
        lights: &Lights,
        settings: &RenderSettings,
    ) -> Self {
        let mut plan = Self::default();
        let origin = camera.position;
        if let Some(sun) = lights
            .sun
            .as_ref()
            .filter(|s| s.shadows.enabled && s.intensity > 0.0)
        {
            plan.cascades = fit_cascades(camera, anchor, aspect, sun.direction, settings);
            let matrices: Vec<Mat4> = plan.cascades.iter().map(|c| c.view_proj).collect();
            for (i, view_proj) in matrices.into_iter().enumerate() {
                plan.push(view_proj, ShadowTarget::Cascade(i as u32));
            }
        }
        let resolution = settings.local_shadow_resolution.max(1);
        let mut spot_budget = settings.max_spot_shadows;
        for spot in lights.spots.iter().take(MAX_SPOT_LIGHTS) {
            let casts = spot.shadows.enabled
                && spot_budget > 0
                && plan.local_layers < MAX_LOCAL_SHADOW_LAYERS as u32;
            if !casts {
                plan.spots.push(None);
                continue;
            }
            spot_budget -= 1;
            let (view_proj, fov) = spot_view(
                spot.position - origin,
                spot.direction,
                spot.outer_angle,
                spot.range,
            );
            let layer = plan.local_layers;
            plan.local_layers += 1;
            plan.push(view_proj, ShadowTarget::Local(layer));
            plan.spots.push(Some(LocalShadow {
                layer,
                near: local_near(spot.range),
                far: spot.range.max(0.05),
                texel_per_metre: 2.0 * (fov * 0.5).tan() / resolution as f32,
            }));
        }
        let mut point_budget = settings.max_point_shadows;
        let margin = settings.shadow_filter_radius + 1.5;
        for point in lights.points.iter().take(MAX_POINT_LIGHTS) {
            let casts = point.shadows.enabled
                && point_budget > 0
                && plan.local_layers + 6 <= MAX_LOCAL_SHADOW_LAYERS as u32;
            if !casts {
                plan.points.push(None);
                continue;
            }
            point_budget -= 1;
            let (faces, fov) =
                point_views(point.position - origin, point.range, resolution, margin);
            let layer = plan.local_layers;
            for (i, view_proj) in faces.into_iter().enumerate() {
                plan.push(view_proj, ShadowTarget::Local(layer + i as u32));
            }
            plan.local_layers += 6;
            plan.points.push(Some(LocalShadow {
                layer,
                near: local_near(point.range),
                far: point.range.max(0.05),
                texel_per_metre: 2.0 * (fov * 0.5).tan() / resolution as f32,
            }));
        }
        plan
    }

    fn push(&mut self, view_proj: Mat4, target: ShadowTarget) {
        self.views.push(ShadowView { view_proj, target });
        self.frusta.push(Frustum::from_view_projection(&view_proj));
    }

    /// The matrices of the local layers, layer by layer.
    pub(crate) fn local_matrices(&self) -> impl Iterator<Item = (u32, Mat4)> + '_ {
        self.views.iter().filter_map(|v| match v.target {
            ShadowTarget::Local(layer) => Some((layer, v.view_proj)),
            ShadowTarget::Cascade(_) => None,
        })
    }
}
