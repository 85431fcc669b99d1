//! Reading asset files as users have them: only regular files, bounded in size; text in
//! whatever encoding the exporter wrote; paths written on another system.
//!
//! - `asset_read_error`: [`AssetReadError`], why a file could not be read as an asset.
//! - `asset_file`: [`read_asset_file`], the one way loaders read a file (refuses devices,
//!   FIFOs and folders before opening them, and files over a size limit).
//! - `asset_warning`: [`AssetWarning`], a problem a loader worked around (file, line).
//! - `text_encoding`: [`TextEncoding`] and [`decode_text`]: UTF-8 (BOM stripped), UTF-16
//!   (by its BOM), else Latin-1.
//! - `referenced_path`: [`resolve_referenced_path`], a path one file names, resolved
//!   against that file's folder (backslashes, drive letters, bare-name fallback).

mod asset_file;
mod asset_read_error;
mod asset_warning;
mod referenced_path;
mod text_encoding;

pub use asset_file::{read_asset_file, MAX_ASSET_FILE_BYTES};
pub use asset_read_error::AssetReadError;
pub use asset_warning::AssetWarning;
pub use referenced_path::resolve_referenced_path;
pub use text_encoding::{decode_text, TextEncoding};
