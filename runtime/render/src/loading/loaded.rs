//! [`Loaded`]: what a loader thread hands back.

use std::path::PathBuf;

use crate::mesh::{ModelLoadError, ModelSource};
use crate::texture::{TextureLoadError, TextureSource};

/// One finished load, with the key it was asked for under.
#[derive(Debug)]
pub enum Loaded<K> {
    /// A model file read and decoded (tangents generated), ready for
    /// [`crate::Renderer::upload_model`].
    Model {
        /// The key it was asked for under.
        key: K,
        /// The file.
        path: PathBuf,
        /// The model, or why nothing can be drawn from it.
        result: Result<ModelSource, ModelLoadError>,
    },
    /// An image file decoded with its mip chain, ready for
    /// [`crate::Renderer::upload_texture_as`].
    Texture {
        /// The key it was asked for under.
        key: K,
        /// The file.
        path: PathBuf,
        /// Data (`true`) or sRGB colour, as asked.
        linear: bool,
        /// The image, or why it failed.
        result: Result<TextureSource, TextureLoadError>,
    },
    /// The load panicked (a bug in a decoder): nothing came of it.
    Panicked {
        /// The key it was asked for under.
        key: K,
        /// The file.
        path: PathBuf,
        /// The panic's message.
        message: String,
    },
}

impl<K> Loaded<K> {
    /// The key the load was asked for under.
    pub fn key(&self) -> &K {
        match self {
            Loaded::Model { key, .. }
            | Loaded::Texture { key, .. }
            | Loaded::Panicked { key, .. } => key,
        }
    }
}
