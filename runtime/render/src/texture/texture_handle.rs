//! [`TextureHandle`]: names a texture uploaded to a [`crate::Renderer`].

/// Names a texture uploaded to one [`crate::Renderer`]. Cheap to copy. Textures stay alive as
/// long as the renderer.
#[repr(transparent)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TextureHandle(pub(crate) u32);

impl TextureHandle {
    /// Index of the texture inside its renderer (for diagnostics).
    #[must_use]
    pub fn index(self) -> u32 {
        self.0
    }
}
