//! [`AlphaMode`]: how a material's alpha is used.

/// How a material's alpha is used (glTF `alphaMode`; OBJ `d` / `Tr` below 1 is `Blend`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum AlphaMode {
    /// Alpha ignored: drawn opaque.
    #[default]
    Opaque,
    /// Cut away where alpha is below `cutoff`, opaque elsewhere (foliage, fences); casts
    /// shadows with the same cut.
    Mask {
        /// Alpha threshold, 0..1 (glTF default 0.5).
        cutoff: f32,
    },
    /// Blended over what is behind, drawn after opaque objects, sorted back to front; casts
    /// no shadow.
    Blend,
}

impl AlphaMode {
    /// glTF's default cutoff of [`AlphaMode::Mask`].
    pub const DEFAULT_CUTOFF: f32 = 0.5;

    /// The cutoff (0 for modes that cut nothing).
    #[must_use]
    pub fn cutoff(self) -> f32 {
        match self {
            AlphaMode::Mask { cutoff } => cutoff,
            _ => 0.0,
        }
    }
}
