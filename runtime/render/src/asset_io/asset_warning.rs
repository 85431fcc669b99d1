//! [`AssetWarning`]: something a loader met in a file and worked around.

use std::path::PathBuf;

/// A non-fatal problem in an asset file: the loader went on (skipped the statement, used a
/// default) and says so once, with the line where it has one. Loaders log each warning
/// through `tracing` and return them beside the asset.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AssetWarning {
    /// The file.
    pub path: PathBuf,
    /// 1-based line of the first occurrence, for text formats.
    pub line: Option<usize>,
    /// What was found and what was done about it, as a sentence.
    pub message: String,
}

impl AssetWarning {
    /// A warning about `path`, at `line` when it has one.
    pub fn new(path: impl Into<PathBuf>, line: Option<usize>, message: impl Into<String>) -> Self {
        Self {
            path: path.into(),
            line,
            message: message.into(),
        }
    }
}

impl std::fmt::Display for AssetWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.line {
            Some(line) => write!(
                f,
                "`{}`, line {line}: {}",
                self.path.display(),
                self.message
            ),
            None => write!(f, "`{}`: {}", self.path.display(), self.message),
        }
    }
}
