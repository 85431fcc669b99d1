//! [`AssetReadError`]: why a file could not be read as an asset.

use std::path::PathBuf;

/// Why [`crate::asset_io::read_asset_file`] refused or failed to read a file. Every variant
/// names the file.
#[derive(Debug, thiserror::Error)]
pub enum AssetReadError {
    /// The file does not exist or could not be opened or read.
    #[error("could not read `{}`: {source}; check that the file exists and is readable", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        #[source]
        source: std::io::Error,
    },
    /// The path names a device, a FIFO, a socket or a folder: reading it could block forever
    /// or never end, so it is refused before it is opened.
    #[error("`{}` is {kind}, not a regular file; an asset must be a file on disk", path.display())]
    NotAFile {
        /// The path.
        path: PathBuf,
        /// What it is instead ("a directory", "a FIFO (named pipe)", "a character device", …).
        kind: &'static str,
    },
    /// The file is larger than an asset may be.
    #[error(
        "`{}` is {size} bytes, more than the {limit} bytes an asset file may have; split or \
         compress it",
        path.display()
    )]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// Its size in bytes.
        size: u64,
        /// The limit in bytes.
        limit: u64,
    },
}

impl AssetReadError {
    /// The file the error is about.
    #[must_use]
    pub fn path(&self) -> &std::path::Path {
        match self {
            AssetReadError::Io { path, .. }
            | AssetReadError::NotAFile { path, .. }
            | AssetReadError::TooLarge { path, .. } => path,
        }
    }
}
