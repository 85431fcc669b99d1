//! [`CallFailure`]: how a plugin call failed, as it crosses the boundary.

use abi_stable::{std_types::RString, StableAbi};

/// Whether a plugin call panicked or returned an error.
#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Eq)]
pub enum FailureKind {
    /// The plugin panicked; the panic was caught inside the plugin's image.
    Panicked,
    /// The plugin returned an error (from `on_attach` or `load_state`).
    Returned,
}

/// A failed plugin call.
#[repr(C)]
#[derive(StableAbi, Clone, Debug, PartialEq, Eq)]
pub struct CallFailure {
    /// Panic or returned error.
    pub kind: FailureKind,
    /// The panic message (with its location when known) or the error's text.
    pub message: RString,
}
