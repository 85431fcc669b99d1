//! [`ShaderSource`]: where WGSL text comes from: a folder on disk (reloadable) or the copies
//! embedded in the binary.

use std::path::{Path, PathBuf};

use super::shader_error::ShaderError;

/// File prepended to every shader (shared structs and lighting).
pub(crate) const COMMON_FILE: &str = "common.wgsl";

/// The workspace `shaders/` folder, embedded at build time.
const EMBEDDED: &[(&str, &str)] = &[
    (
        "common.wgsl",
        include_str!("../../../../shaders/common.wgsl"),
    ),
    ("unlit.wgsl", include_str!("../../../../shaders/unlit.wgsl")),
    (
        "lit_low.wgsl",
        include_str!("../../../../shaders/lit_low.wgsl"),
    ),
    ("lit.wgsl", include_str!("../../../../shaders/lit.wgsl")),
    (
        "normal.wgsl",
        include_str!("../../../../shaders/normal.wgsl"),
    ),
    (
        "wireframe.wgsl",
        include_str!("../../../../shaders/wireframe.wgsl"),
    ),
    ("grid.wgsl", include_str!("../../../../shaders/grid.wgsl")),
    (
        "debug_lines.wgsl",
        include_str!("../../../../shaders/debug_lines.wgsl"),
    ),
    (
        "placeholder.wgsl",
        include_str!("../../../../shaders/placeholder.wgsl"),
    ),
];

/// Where shader text is read from.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ShaderSource {
    dir: Option<PathBuf>,
}

impl ShaderSource {
    /// The shaders embedded in the binary (always available, never change).
    #[must_use]
    pub fn embedded() -> Self {
        Self { dir: None }
    }

    /// Shaders read from `dir` each time they are (re)loaded.
    #[must_use]
    pub fn from_dir(dir: impl Into<PathBuf>) -> Self {
        Self {
            dir: Some(dir.into()),
        }
    }

    /// The folder shaders are read from, if any.
    #[must_use]
    pub fn dir(&self) -> Option<&Path> {
        self.dir.as_deref()
    }

    /// The full text of shader `file`: `common.wgsl` followed by the file itself.
    ///
    /// # Errors
    /// [`ShaderError::Read`] when a file cannot be read from the folder.
    pub fn read(&self, file: &str) -> Result<String, ShaderError> {
        let common = self.read_one(COMMON_FILE)?;
        let body = self.read_one(file)?;
        Ok(format!("{common}\n// ---- {file} ----\n{body}"))
    }

    /// The embedded text of shader `file` with `common.wgsl` prepended.
    pub(crate) fn read_embedded(file: &str) -> String {
        format!(
            "{}\n// ---- {file} ----\n{}",
            embedded(COMMON_FILE),
            embedded(file)
        )
    }

    fn read_one(&self, file: &str) -> Result<String, ShaderError> {
        match &self.dir {
            Some(dir) => {
                let path = dir.join(file);
                std::fs::read_to_string(&path).map_err(|source| ShaderError::Read { path, source })
            }
            None => Ok(embedded(file).to_owned()),
        }
    }
}

fn embedded(file: &str) -> &'static str {
    EMBEDDED
        .iter()
        .find(|(name, _)| *name == file)
        .map_or("", |(_, text)| text)
}
