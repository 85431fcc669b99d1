//! [`MeshHandle`]: names a mesh uploaded to a [`crate::Renderer`].

/// Names a mesh uploaded to one [`crate::Renderer`]. Cheap to copy, store it in components.
/// Meshes stay alive as long as the renderer (they are never freed in this version).
#[repr(transparent)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct MeshHandle(pub(crate) u32);

impl MeshHandle {
    /// Index of the mesh inside its renderer (for diagnostics).
    #[must_use]
    pub fn index(self) -> u32 {
        self.0
    }
}
