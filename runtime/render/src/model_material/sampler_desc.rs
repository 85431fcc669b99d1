//! [`SamplerDesc`] and [`WrapMode`]: how a texture is filtered and tiled.

/// How texture coordinates outside 0..1 are treated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum WrapMode {
    /// Tiled (the default).
    #[default]
    Repeat,
    /// Tiled, every other tile mirrored.
    MirroredRepeat,
    /// The edge texel continues.
    ClampToEdge,
}

/// A texture's sampler as the file gives it (glTF samplers). The renderer samples every
/// texture with repeat and trilinear filtering for now; this is carried for when it does not.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SamplerDesc {
    /// Horizontal wrapping.
    pub wrap_u: WrapMode,
    /// Vertical wrapping.
    pub wrap_v: WrapMode,
    /// Magnification: linear (else nearest).
    pub mag_linear: bool,
    /// Minification: linear (else nearest).
    pub min_linear: bool,
    /// Whether mip levels are sampled.
    pub mipmaps: bool,
}

impl Default for SamplerDesc {
    fn default() -> Self {
        Self {
            wrap_u: WrapMode::Repeat,
            wrap_v: WrapMode::Repeat,
            mag_linear: true,
            min_linear: true,
            mipmaps: true,
        }
    }
}
