//! [`SceneError`]: why a scene could not be loaded or saved.

use std::path::{Path, PathBuf};

/// A scene that could not be read or written. Loading never changes the world on error;
/// saving never damages the previous file.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SceneError {
    /// The file could not be read or written.
    // The cause is in the sentence, not chained as a `source` (printed twice otherwise).
    #[error("could not {action} scene `{}`: {cause}", .path.display())]
    Io {
        /// "read" or "write".
        action: &'static str,
        /// The file.
        path: PathBuf,
        /// The I/O error.
        cause: std::io::Error,
    },
    /// The file is not valid scene RON.
    #[error("scene `{}` is malformed at line {line}, column {column}: {message}", .path.display())]
    Parse {
        /// The file.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// The parser's message.
        message: String,
    },
    /// The file is of a format version this host does not read.
    #[error(
        "scene `{}` has format version {found}, this host reads versions {oldest} to {newest}",
        .path.display()
    )]
    UnsupportedVersion {
        /// The file.
        path: PathBuf,
        /// Its version.
        found: u32,
        /// The oldest version this host reads.
        oldest: u32,
        /// The version this host writes.
        newest: u32,
    },
    /// An entity of the file cannot be spawned: a bad value, or a parent that is not there or
    /// makes a cycle.
    #[error("scene `{}`, entity #{index}{}: {message}", .path.display(), named(.name))]
    InvalidEntity {
        /// The file.
        path: PathBuf,
        /// 0-based index of the entity in the file.
        index: usize,
        /// Its `name`, if it has one.
        name: Option<String>,
        /// What is wrong.
        message: String,
    },
    /// The scene's physics settings are not acceptable.
    #[error("scene `{}`: {message}", .path.display())]
    InvalidPhysics {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// The import settings the scene gives a model are out of range.
    #[error("scene `{}`, import settings of `{model}`: {message}", .path.display())]
    InvalidImport {
        /// The file.
        path: PathBuf,
        /// The model they are for.
        model: String,
        /// What is wrong.
        message: String,
    },
    /// A glTF file opened as a scene could not be imported.
    #[error(transparent)]
    Gltf(#[from] super::GltfImportError),
    /// The world could not be serialized.
    #[error("could not serialize the scene: {message}")]
    Serialize {
        /// The serializer's message.
        message: String,
    },
}

fn named(name: &Option<String>) -> String {
    match name {
        Some(name) => format!(" ({name:?})"),
        None => String::new(),
    }
}

impl SceneError {
    /// The file the error is about, if any.
    pub fn path(&self) -> Option<&Path> {
        match self {
            SceneError::Io { path, .. }
            | SceneError::Parse { path, .. }
            | SceneError::UnsupportedVersion { path, .. }
            | SceneError::InvalidEntity { path, .. }
            | SceneError::InvalidPhysics { path, .. }
            | SceneError::InvalidImport { path, .. } => Some(path),
            SceneError::Gltf(error) => Some(error.path()),
            SceneError::Serialize { .. } => None,
        }
    }
}
