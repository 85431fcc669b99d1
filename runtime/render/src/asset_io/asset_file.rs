//! [`read_asset_file`]: the one way loaders read a file from disk.

use std::io::Read;
use std::path::Path;

use super::asset_read_error::AssetReadError;

/// Largest asset file read, bytes (2 GiB): a 2M-triangle OBJ is about 150 MB, the largest
/// glTF samples about 50 MB. Larger files are refused before any byte is read.
pub const MAX_ASSET_FILE_BYTES: u64 = 2 << 30;

/// Reads a whole asset file, at most `limit` bytes.
///
/// Only regular files are read: a device (`/dev/zero` would read until memory runs out), a
/// FIFO (opening one blocks until a writer comes) or a folder is refused from its metadata,
/// before it is opened. A file that grows past `limit` while it is read is refused too.
///
/// # Errors
/// [`AssetReadError`] naming the file.
pub fn read_asset_file(path: &Path, limit: u64) -> Result<Vec<u8>, AssetReadError> {
    let io = |source| AssetReadError::Io {
        path: path.to_owned(),
        source,
    };
    let metadata = std::fs::metadata(path).map_err(io)?;
    let kind = metadata.file_type();
    if !kind.is_file() {
        return Err(AssetReadError::NotAFile {
            path: path.to_owned(),
            kind: describe(&kind),
        });
    }
    if metadata.len() > limit {
        return Err(AssetReadError::TooLarge {
            path: path.to_owned(),
            size: metadata.len(),
            limit,
        });
    }
    let file = std::fs::File::open(path).map_err(io)?;
    let mut bytes = Vec::with_capacity(usize::try_from(metadata.len()).unwrap_or(0));
    // One byte past the limit tells a file that grew since its metadata was read.
    file.take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > limit {
        return Err(AssetReadError::TooLarge {
            path: path.to_owned(),
            size: bytes.len() as u64,
            limit,
        });
    }
    Ok(bytes)
}

/// What a non-regular file is, for the error sentence.
fn describe(kind: &std::fs::FileType) -> &'static str {
    if kind.is_dir() {
        return "a directory";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if kind.is_char_device() {
            return "a character device";
        }
        if kind.is_block_device() {
            return "a block device";
        }
        if kind.is_socket() {
            return "a socket";
        }
    }
    "not a regular file"
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn devices_and_folders_are_refused_before_reading() {
        #[cfg(unix)]
        match read_asset_file(Path::new("/dev/zero"), MAX_ASSET_FILE_BYTES) {
            Err(AssetReadError::NotAFile { kind, .. }) => assert_eq!(kind, "a character device"),
            other => panic!("/dev/zero must be refused, got {other:?}"),
        }
        let dir = std::env::temp_dir();
        match read_asset_file(&dir, MAX_ASSET_FILE_BYTES) {
            Err(error @ AssetReadError::NotAFile { .. }) => {
                assert!(error.to_string().contains("a directory"), "{error}");
            }
            other => panic!("a folder must be refused, got {other:?}"),
        }
    }

    #[test]
    fn a_file_over_the_limit_is_refused_with_its_size() {
        let dir = std::env::temp_dir().join(format!("onyx-asset-file-{}", std::process::id()));
        let _ = std::fs::create_dir_all(&dir);
        let path = dir.join("ten.bin");
        std::fs::write(&path, [7u8; 10]).unwrap_or_else(|e| panic!("{e}"));
        match read_asset_file(&path, 9) {
            Err(AssetReadError::TooLarge { size, limit, .. }) => assert_eq!((size, limit), (10, 9)),
            other => panic!("expected TooLarge, got {other:?}"),
        }
        assert_eq!(read_asset_file(&path, 10).ok(), Some(vec![7u8; 10]));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
