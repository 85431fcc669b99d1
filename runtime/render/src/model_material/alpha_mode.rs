//! [`AlphaMode`]: how a material's alpha is used.

/// How a material's alpha is used (glTF `alphaMode`; OBJ `d` < 1 is `Blend`). The renderer
/// draws every material opaque for now; the mode is carried for the one that will not.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum AlphaMode {
    /// Alpha ignored.
    #[default]
    Opaque,
    /// Fully transparent below `cutoff`, opaque above.
    Mask {
        /// Alpha threshold, 0..1 (glTF default 0.5).
        cutoff: f32,
    },
    /// Blended over what is behind.
    Blend,
}
