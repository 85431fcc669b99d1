//! [`write_atomically`]: replace a file's content all at once or not at all, and never
//! replace what is not a file.

use std::io::Write;
use std::path::{Path, PathBuf};

/// Permissions asked for a new file (the process's umask then applies, as for any file a
/// program creates).
#[cfg(unix)]
const NEW_FILE_MODE: u32 = 0o666;

/// Longest chain of symbolic links followed to the file written (a longer one is a loop).
const MAX_SYMLINKS: usize = 40;

/// Writes `bytes` to `path` through a temporary file in the same directory, flushed to disk,
/// then renamed over the file: a crash or an error leaves the previous file intact.
///
/// What is at `path` is respected:
/// - a symbolic link is followed, and the file it points to is replaced (the link stays a
///   link);
/// - an existing file keeps its permissions; a new one gets the usual ones (0666 less the
///   umask), not the temporary file's 0600;
/// - a read-only file, a directory, a device, a FIFO or a socket is refused with an error
///   saying what it is, and nothing is written.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let target = resolve_links(path)?;
    let existing = match std::fs::metadata(&target) {
        Ok(metadata) => Some(metadata),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => None,
        Err(e) => return Err(e),
    };
    if let Some(metadata) = &existing {
        if !metadata.is_file() {
            return Err(refused(
                &target,
                &format!("is {}, not a file", kind(metadata)),
            ));
        }
        if metadata.permissions().readonly() {
            return Err(refused(
                &target,
                "is read-only; make it writable or save under another name",
            ));
        }
    }
    let dir = match target.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let mut builder = tempfile::Builder::new();
    builder.prefix(".onyx-save-");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        builder.permissions(std::fs::Permissions::from_mode(NEW_FILE_MODE));
    }
    if !dir.is_dir() {
        return Err(std::io::Error::new(
            std::io::ErrorKind::NotFound,
            format!("the folder `{}` does not exist", dir.display()),
        ));
    }
    let mut tmp = builder.tempfile_in(dir).map_err(|e| {
        // Said of the folder: the temporary file's own name means nothing to the user.
        let why = match e.kind() {
            std::io::ErrorKind::PermissionDenied => "permission denied".to_owned(),
            std::io::ErrorKind::ReadOnlyFilesystem => "the file system is read-only".to_owned(),
            std::io::ErrorKind::StorageFull => "the disk is full".to_owned(),
            kind => kind.to_string(),
        };
        std::io::Error::new(
            e.kind(),
            format!("cannot create a file in `{}`: {why}", dir.display()),
        )
    })?;
    tmp.write_all(bytes)?;
    if let Some(metadata) = &existing {
        tmp.as_file().set_permissions(metadata.permissions())?;
    }
    tmp.as_file().sync_all()?;
    tmp.persist(&target).map_err(|e| e.error)?;
    Ok(())
}

/// `path` with every symbolic link along it followed to the file it names (which may not
/// exist yet).
fn resolve_links(path: &Path) -> std::io::Result<PathBuf> {
    let mut at = path.to_path_buf();
    for _ in 0..MAX_SYMLINKS {
        match std::fs::symlink_metadata(&at) {
            Ok(m) if m.file_type().is_symlink() => {
                let link = std::fs::read_link(&at)?;
                at = match at.parent() {
                    Some(dir) if link.is_relative() => dir.join(link),
                    _ => link,
                };
            }
            _ => return Ok(at),
        }
    }
    Err(refused(path, "is a loop of symbolic links"))
}

fn kind(metadata: &std::fs::Metadata) -> &'static str {
    let t = metadata.file_type();
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt as _;
        if t.is_block_device() || t.is_char_device() {
            return "a device";
        }
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if t.is_dir() {
        "a directory"
    } else {
        "not a regular file"
    }
}

fn refused(path: &Path, why: &str) -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::InvalidInput,
        format!("`{}` {why}: nothing was written", path.display()),
    )
}

#[cfg(all(test, unix))]
mod tests {
    use std::os::unix::fs::{FileTypeExt as _, PermissionsExt as _};

    use super::*;

    fn mode(path: &Path) -> u32 {
        std::fs::metadata(path).unwrap().permissions().mode() & 0o777
    }

    #[test]
    fn a_new_file_gets_the_usual_permissions_and_an_old_one_keeps_its_own() {
        let dir = tempfile::tempdir().unwrap();
        let new = dir.path().join("new.ron");
        write_atomically(&new, b"one").unwrap();
        assert_eq!(std::fs::read(&new).unwrap(), b"one");
        // The usual mode is 0666 less the umask: group or world can read it (umask 077 is rare
        // and would give 0600, which the old code gave always).
        let m = mode(&new);
        assert!(m & 0o600 == 0o600 && m & 0o044 != 0, "mode {m:o}");

        let kept = dir.path().join("kept.ron");
        std::fs::write(&kept, b"old").unwrap();
        std::fs::set_permissions(&kept, std::fs::Permissions::from_mode(0o640)).unwrap();
        write_atomically(&kept, b"new").unwrap();
        assert_eq!(std::fs::read(&kept).unwrap(), b"new");
        assert_eq!(mode(&kept), 0o640, "the file keeps its permissions");
    }

    #[test]
    fn a_symlink_is_followed_and_stays_a_link() {
        let dir = tempfile::tempdir().unwrap();
        let real = dir.path().join("real.ron");
        std::fs::write(&real, b"old").unwrap();
        let link = dir.path().join("link.ron");
        std::os::unix::fs::symlink("real.ron", &link).unwrap();
        write_atomically(&link, b"new").unwrap();
        assert!(std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read(&real).unwrap(), b"new");
    }

    #[test]
    fn a_read_only_file_a_directory_and_a_fifo_are_refused_and_left_alone() {
        let dir = tempfile::tempdir().unwrap();
        let locked = dir.path().join("locked.ron");
        std::fs::write(&locked, b"keep").unwrap();
        std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o444)).unwrap();
        let error = write_atomically(&locked, b"lost").unwrap_err();
        assert!(error.to_string().contains("read-only"), "{error}");
        assert_eq!(std::fs::read(&locked).unwrap(), b"keep");

        let error = write_atomically(dir.path(), b"x").unwrap_err();
        assert!(error.to_string().contains("a directory"), "{error}");

        let fifo = dir.path().join("fifo");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if made.is_ok_and(|s| s.success()) {
            let error = write_atomically(&fifo, b"x").unwrap_err();
            assert!(error.to_string().contains("a FIFO"), "{error}");
            assert!(std::fs::symlink_metadata(&fifo)
                .unwrap()
                .file_type()
                .is_fifo());
        }
        let error = write_atomically(Path::new("/dev/null"), b"x").unwrap_err();
        assert!(error.to_string().contains("a device"), "{error}");
        let leftovers: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .flatten()
            .filter(|e| e.file_name().to_string_lossy().starts_with(".onyx-save-"))
            .collect();
        assert!(leftovers.is_empty(), "temporary files left behind");
    }
}
