//! [`ImageSource`]: where a texture's pixels are.

use std::path::PathBuf;

/// Where a texture's pixels are.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum ImageSource {
    /// An image file (resolved against the file that names it).
    File(PathBuf),
    /// Image `index` of a model file (a glTF `data:` URI or a GLB buffer view).
    Embedded {
        /// The model file.
        model: PathBuf,
        /// The glTF image index.
        index: usize,
    },
}

impl std::fmt::Display for ImageSource {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ImageSource::File(path) => write!(f, "{}", path.display()),
            ImageSource::Embedded { model, index } => {
                write!(f, "{}#image{index}", model.display())
            }
        }
    }
}
