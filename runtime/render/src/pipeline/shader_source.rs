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
    (
        "material.wgsl",
        include_str!("../../../../shaders/material.wgsl"),
    ),
    (
        "lighting.wgsl",
        include_str!("../../../../shaders/lighting.wgsl"),
    ),
    ("sky.wgsl", include_str!("../../../../shaders/sky.wgsl")),
    (
        "shadow.wgsl",
        include_str!("../../../../shaders/shadow.wgsl"),
    ),
    (
        "tonemap.wgsl",
        include_str!("../../../../shaders/tonemap.wgsl"),
    ),
    (
        "environment.wgsl",
        include_str!("../../../../shaders/environment.wgsl"),
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
        self.read_with(file, &[])
    }

    /// The full text of shader `file`: `common.wgsl`, then each of `preludes`, then the file.
    ///
    /// # Errors
    /// [`ShaderError::Read`] when a file cannot be read from the folder.
    pub fn read_with(&self, file: &str, preludes: &[&str]) -> Result<String, ShaderError> {
        let mut text = self.read_one(COMMON_FILE)?;
        for prelude in preludes.iter().chain(std::iter::once(&file)) {
            let body = self.read_one(prelude)?;
            text.push_str(&format!("\n// ---- {prelude} ----\n{body}"));
        }
        Ok(text)
    }

    /// The text of shader `file` alone (a shader that does not share `common.wgsl`, such as
    /// the sky bake).
    ///
    /// # Errors
    /// [`ShaderError::Read`] when the file cannot be read from the folder.
    pub fn read_standalone(&self, file: &str) -> Result<String, ShaderError> {
        self.read_one(file)
    }

    /// The embedded text of shader `file` alone.
    pub(crate) fn read_embedded_standalone(file: &str) -> String {
        embedded(file).to_owned()
    }

    /// The embedded text of shader `file` with `common.wgsl` and `preludes` prepended.
    pub(crate) fn read_embedded(file: &str, preludes: &[&str]) -> String {
        let mut text = embedded(COMMON_FILE).to_owned();
        for prelude in preludes.iter().chain(std::iter::once(&file)) {
            text.push_str(&format!("\n// ---- {prelude} ----\n{}", embedded(prelude)));
        }
        text
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
