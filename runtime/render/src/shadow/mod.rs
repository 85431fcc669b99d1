//! Shadows: which lights cast them this frame and from where ([`ShadowPlan`]), and the depth
//! textures they are drawn into ([`ShadowMaps`]).
//!
//! - `cascades`: the directional light's cascades, fitted to slices of the camera's view and
//!   snapped to whole texels so they do not shimmer as the camera moves.
//! - `shadow_anchor`: [`ShadowAnchor`], the point the cascades' texel grid is laid from (where
//!   the camera first was), so a scene shadows alike wherever it is placed.
//! - `local_shadows`: the views of spot lights (one) and point lights (six cube faces).
//! - `shadow_plan`: [`ShadowPlan`], every shadow view of a frame with the shader's data.
//! - `shadow_maps`: [`ShadowMaps`], the directional and local depth arrays.

mod cascades;
mod local_shadows;
mod shadow_anchor;
mod shadow_maps;
mod shadow_plan;

pub(crate) use shadow_anchor::ShadowAnchor;
pub(crate) use shadow_maps::{ShadowMaps, SHADOW_FORMAT};
pub(crate) use shadow_plan::{LocalShadow, ShadowPlan, ShadowTarget};

/// Most directional cascades.
pub const MAX_CASCADES: usize = 4;
/// Most layers of the local (spot and point) shadow array: every view of a frame's shadowed
/// spot and point lights.
pub(crate) const MAX_LOCAL_SHADOW_LAYERS: usize = 16;
/// How far behind a cascade (towards the light) casters still throw shadows into it, metres.
pub(crate) const CASCADE_CASTER_REACH: f32 = 250.0;
