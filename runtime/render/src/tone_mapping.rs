//! [`ToneMapping`]: how the HDR frame is mapped to the display.

/// The operator that maps the HDR frame (after exposure) to displayable 0..1 values, before
/// sRGB encoding.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ToneMapping {
    /// AgX (Troy Sobotka's, as Blender 4 and Bevy ship it): bright colours desaturate towards
    /// white as real film does, instead of clipping to pure hues. The default.
    #[default]
    AgX,
    /// ACES filmic (Narkowicz's fit): more contrast, saturated highlights shift hue.
    Aces,
    /// Reinhard on luminance: gentle, keeps hues, greyer.
    Reinhard,
    /// No operator: values above 1 clip (for comparisons and debugging).
    None,
}

impl ToneMapping {
    /// The value `tonemap.wgsl` switches on.
    pub(crate) const fn shader_index(self) -> u32 {
        match self {
            ToneMapping::AgX => 0,
            ToneMapping::Aces => 1,
            ToneMapping::Reinhard => 2,
            ToneMapping::None => 3,
        }
    }
}
