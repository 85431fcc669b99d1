//! [`resolve_referenced_path`]: where a file named inside another file is.

use std::path::{Path, PathBuf};

/// Finds the file that a model or material file names (`mtllib`, `map_Kd`, a glTF `uri`),
/// as exporters on any system write it:
///
/// - relative to `folder`, the folder of the file that names it (never the working
///   directory);
/// - backslashes are separators (`tex\wood.png`, `.\wood.png`);
/// - a Windows drive or an absolute path that does not exist here (`C:\Users\me\wood.png`,
///   `/home/them/wood.png`) is tried as written, then by its path below the drive;
/// - when nothing else is found, the bare file name beside the naming file.
///
/// Returns the first candidate that exists, else the first candidate (so the error names
/// where the file was expected).
#[must_use]
pub fn resolve_referenced_path(folder: &Path, written: &str) -> PathBuf {
    let candidates = candidates(folder, written.trim());
    candidates
        .iter()
        .find(|c| c.is_file())
        .or_else(|| candidates.first())
        .cloned()
        .unwrap_or_else(|| folder.join(written))
}

/// The places `written` may mean, most likely first.
fn candidates(folder: &Path, written: &str) -> Vec<PathBuf> {
    let slashed = written.replace('\\', "/");
    let mut out = Vec::new();
    let drive = slashed.len() >= 2
        && slashed.as_bytes()[1] == b':'
        && slashed.as_bytes()[0].is_ascii_alphabetic();
    let below_drive = if drive { &slashed[2..] } else { &slashed[..] };
    let relative = below_drive.trim_start_matches('/');
    if Path::new(&slashed).is_absolute() && !drive {
        out.push(PathBuf::from(&slashed));
    }
    out.push(folder.join(relative));
    if let Some(name) = Path::new(relative).file_name() {
        let beside = folder.join(name);
        if !out.contains(&beside) {
            out.push(beside);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn windows_paths_are_split_on_backslashes_and_fall_back_to_the_bare_name() {
        let dir = std::env::temp_dir().join(format!("onyx-refpath-{}", std::process::id()));
        let _ = std::fs::create_dir_all(dir.join("tex"));
        let touch = |p: &Path| std::fs::write(p, b"x").unwrap_or_else(|e| panic!("{e}"));
        touch(&dir.join("tex/a.png"));
        touch(&dir.join("b.png"));
        assert_eq!(
            resolve_referenced_path(&dir, "tex\\a.png"),
            dir.join("tex/a.png")
        );
        assert_eq!(
            resolve_referenced_path(&dir, ".\\b.png"),
            dir.join("./b.png")
        );
        assert_eq!(
            resolve_referenced_path(&dir, "C:\\Users\\me\\textures\\b.png"),
            dir.join("b.png")
        );
        assert_eq!(
            resolve_referenced_path(&dir, "/home/them/b.png"),
            dir.join("b.png")
        );
        // Missing everywhere: the first place tried, for the error message.
        assert_eq!(
            resolve_referenced_path(&dir, "gone\\c.png"),
            dir.join("gone/c.png")
        );
        let _ = std::fs::remove_dir_all(&dir);
    }
}
