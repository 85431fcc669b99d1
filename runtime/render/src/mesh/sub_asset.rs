//! [`SubAsset`]: a reference to one piece of a model file, written after a `#` in its path
//! (`city.glb#mesh/3`), so a scene can draw one mesh of a glTF file without the rest.

use std::path::{Path, PathBuf};

/// One piece of a model file. Written `FILE#mesh/N` ([`SubAsset::path_in`]); only glTF files
/// have pieces.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SubAsset {
    /// Mesh `N` of the file (`#mesh/N`), all its primitives, in the mesh's own space.
    Mesh(usize),
    /// Animation `N` of the file (`#animation/N`).
    Animation(usize),
}

impl SubAsset {
    /// Splits `path` into the file and the piece it names: `a/b.glb#mesh/2` gives
    /// (`a/b.glb`, `Some(Mesh(2))`). A path whose tail is not `#mesh/N` or `#animation/N`
    /// after a `.gltf`/`.glb` file is returned whole with `None` (a file may have `#` in
    /// its name).
    #[must_use]
    pub fn split(path: &Path) -> (PathBuf, Option<SubAsset>) {
        let whole = || (path.to_path_buf(), None);
        let Some(text) = path.to_str() else {
            return whole();
        };
        let Some((file, fragment)) = text.rsplit_once('#') else {
            return whole();
        };
        let Some((kind, index)) = fragment.split_once('/') else {
            return whole();
        };
        if !super::is_gltf(Path::new(file))
            || index.is_empty()
            || !index.bytes().all(|b| b.is_ascii_digit())
        {
            return whole();
        }
        let Ok(index) = index.parse::<usize>() else {
            return whole();
        };
        let sub = match kind {
            "mesh" => SubAsset::Mesh(index),
            "animation" => SubAsset::Animation(index),
            _ => return whole(),
        };
        (PathBuf::from(file), Some(sub))
    }

    /// The path naming this piece of `file` (`file#mesh/N`).
    #[must_use]
    pub fn path_in(self, file: &Path) -> PathBuf {
        let mut text = file.as_os_str().to_owned();
        text.push(format!("#{self}"));
        PathBuf::from(text)
    }
}

impl std::fmt::Display for SubAsset {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SubAsset::Mesh(index) => write!(f, "mesh/{index}"),
            SubAsset::Animation(index) => write!(f, "animation/{index}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mesh_reference_splits_and_joins_back() {
        let (file, sub) = SubAsset::split(Path::new("models/city.glb#mesh/12"));
        assert_eq!(file, Path::new("models/city.glb"));
        assert_eq!(sub, Some(SubAsset::Mesh(12)));
        assert_eq!(
            SubAsset::Mesh(12).path_in(&file),
            Path::new("models/city.glb#mesh/12")
        );
        assert_eq!(
            SubAsset::split(Path::new("a.gltf#animation/0")).1,
            Some(SubAsset::Animation(0))
        );
    }

    #[test]
    fn a_hash_in_a_file_name_is_not_a_reference() {
        for written in [
            "odd#name.obj",
            "model.obj#mesh/1",
            "a.glb#mesh/",
            "a.glb#mesh/-1",
            "a.glb#mesh/1x",
            "a.glb#node/1",
            "a.glb#mesh/99999999999999999999999",
        ] {
            let (file, sub) = SubAsset::split(Path::new(written));
            assert_eq!(
                (file.as_path(), sub),
                (Path::new(written), None),
                "{written}"
            );
        }
    }
}
