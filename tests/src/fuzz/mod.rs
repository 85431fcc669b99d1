//! Mutation fuzzing of every file format Onyx reads: scene files, OBJ, MTL, PNG and JPEG,
//! glTF and GLB, and plugin libraries.
//!
//! - `mutator.rs`: [`mutate`] — a deterministic mutation of a file (same seed and case, same
//!   bytes), so any failing case can be written down as a recipe and replayed.
//! - `format.rs`: [`Format`] — each format's corpus (real files: the repository's scenes and
//!   the sample models under `../shared/fixtures`) and how one case is run through the real
//!   reader.
//!
//! The bounded run is a test (`tests/e2e/fuzz.rs`, a few thousand cases in seconds); the long
//! run is the `onyx-fuzz` binary, which runs cases in child processes so that a signal or a
//! hang is counted and written down instead of ending the run. Failing cases are kept in
//! `tests/fuzz-regressions.txt` and replayed by the test.

mod format;
mod mutator;

pub use format::{Case, Format, Outcome};
pub use mutator::mutate;

/// One failing case, as a line of `tests/fuzz-regressions.txt`:
/// `FORMAT SOURCE SEED CASE` (SOURCE relative to the corpus root the format names).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Recipe {
    /// The format.
    pub format: Format,
    /// The corpus file mutated, relative to its root.
    pub source: String,
    /// The run's seed.
    pub seed: u64,
    /// The case number in the run.
    pub case: u64,
}

impl Recipe {
    /// Parses a line; `None` for blank lines and `#` comments.
    pub fn parse(line: &str) -> Option<Result<Recipe, String>> {
        // What follows `#` is a comment (the recorder writes why the case failed there).
        let line = line
            .split_once('#')
            .map_or(line, |(recipe, _)| recipe)
            .trim();
        if line.is_empty() {
            return None;
        }
        let words: Vec<&str> = line.split_whitespace().collect();
        let [format, source, seed, case] = words[..] else {
            return Some(Err(format!("`{line}` is not FORMAT SOURCE SEED CASE")));
        };
        let parsed = (|| {
            Ok(Recipe {
                format: Format::from_name(format).ok_or(format!("unknown format `{format}`"))?,
                source: source.to_owned(),
                seed: seed.parse().map_err(|e| format!("seed `{seed}`: {e}"))?,
                case: case.parse().map_err(|e| format!("case `{case}`: {e}"))?,
            })
        })();
        Some(parsed)
    }
}

impl std::fmt::Display for Recipe {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} {} {} {}",
            self.format.name(),
            self.source,
            self.seed,
            self.case
        )
    }
}
