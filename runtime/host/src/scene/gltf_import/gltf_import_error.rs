//! [`GltfImportError`]: why a glTF file could not be brought in as entities.

use std::path::PathBuf;

/// A glTF file that cannot be imported as a scene. Nothing is spawned on error.
#[derive(Debug, thiserror::Error)]
pub enum GltfImportError {
    /// The file could not be read (missing, not a regular file, too large).
    #[error("could not read glTF file `{}`: {message}", .path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// Why, as the reader says it.
        message: String,
    },
    /// The file is not valid glTF 2.0.
    #[error("`{}` is not a valid glTF 2.0 file ({message}); re-export it", .path.display())]
    Invalid {
        /// The file.
        path: PathBuf,
        /// The parser's message.
        message: String,
    },
    /// The file requires an extension Onyx does not implement.
    #[error(
        "`{}` requires the glTF extension `{extension}`, which Onyx does not support; \
         re-export it without that extension",
        .path.display()
    )]
    RequiredExtension {
        /// The file.
        path: PathBuf,
        /// The extension.
        extension: String,
    },
}

impl GltfImportError {
    /// The file at fault.
    pub fn path(&self) -> &std::path::Path {
        match self {
            GltfImportError::Read { path, .. }
            | GltfImportError::Invalid { path, .. }
            | GltfImportError::RequiredExtension { path, .. } => path,
        }
    }
}
