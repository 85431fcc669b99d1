//! [`LightShadows`]: whether a light casts shadows, and the biases that keep them clean.

/// Shadow switch and biases of one light.
///
/// Both biases move the point a surface is tested at, before the shadow map is read:
/// `depth_bias` towards the light, `normal_bias` along the surface normal. Too little shows
/// *acne* (dark speckles and stripes on lit surfaces); too much detaches shadows from their
/// casters (*peter-panning*) and lets light leak under thin objects.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightShadows {
    /// Whether the light casts shadows. Default: on for directional lights, off for point
    /// and spot lights (each costs one or six extra passes per frame).
    pub enabled: bool,
    /// Metres towards the light. Default [`LightShadows::DIRECTIONAL_DEPTH_BIAS`] (0.02) for
    /// directional lights, [`LightShadows::LOCAL_DEPTH_BIAS`] (0.03) for point and spot lights.
    pub depth_bias: f32,
    /// Shadow-map texels along the surface normal (so it scales with each cascade's texel
    /// size). Default [`LightShadows::DIRECTIONAL_NORMAL_BIAS`] (1.8) for directional lights,
    /// [`LightShadows::LOCAL_NORMAL_BIAS`] (0.8) for point and spot lights.
    pub normal_bias: f32,
}

impl LightShadows {
    /// Default depth bias of directional lights, metres.
    pub const DIRECTIONAL_DEPTH_BIAS: f32 = 0.02;
    /// Default normal bias of directional lights, texels.
    pub const DIRECTIONAL_NORMAL_BIAS: f32 = 1.8;
    /// Default depth bias of point and spot lights, metres.
    pub const LOCAL_DEPTH_BIAS: f32 = 0.03;
    /// Default normal bias of point and spot lights, texels.
    pub const LOCAL_NORMAL_BIAS: f32 = 0.8;

    /// Shadows on, with the directional defaults.
    #[must_use]
    pub const fn directional() -> Self {
        Self {
            enabled: true,
            depth_bias: Self::DIRECTIONAL_DEPTH_BIAS,
            normal_bias: Self::DIRECTIONAL_NORMAL_BIAS,
        }
    }

    /// Shadows off, with the point/spot defaults for when they are turned on.
    #[must_use]
    pub const fn local() -> Self {
        Self {
            enabled: false,
            depth_bias: Self::LOCAL_DEPTH_BIAS,
            normal_bias: Self::LOCAL_NORMAL_BIAS,
        }
    }

    /// The same biases with shadows on or off.
    #[must_use]
    pub const fn with_enabled(mut self, enabled: bool) -> Self {
        self.enabled = enabled;
        self
    }
}
