//! [`SettingsError`]: why a [`crate::PhysicsSettings`] cannot be simulated.

use std::fmt;

/// A settings field outside the values the engine can simulate (see
/// [`crate::PhysicsSettings::validate`]).
#[derive(Clone, Debug, PartialEq)]
pub enum SettingsError {
    /// A number that must be finite and within a range is not.
    OutOfRange {
        /// The field, as named in `PhysicsSettings` (and in scene files).
        field: &'static str,
        /// The value given.
        value: f64,
        /// What it must be, in words ("> 0", "in [0, 1]").
        expected: &'static str,
    },
}

impl fmt::Display for SettingsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SettingsError::OutOfRange {
                field,
                value,
                expected,
            } => write!(f, "physics.{field} must be {expected}, got {value}"),
        }
    }
}

impl std::error::Error for SettingsError {}
