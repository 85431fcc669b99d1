//! [`CallError`]: a plugin call that panicked or returned an error.

use crate::__ffi::{CallFailure, FailureKind};

/// A lifecycle call that did not complete.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum CallError {
    /// The plugin panicked; `message` is the panic message and location.
    #[error("panicked: {message}")]
    Panicked {
        /// Panic message, with its source location when known.
        message: String,
    },
    /// The plugin returned an error.
    #[error("returned an error: {message}")]
    Returned {
        /// The error's text.
        message: String,
    },
}

impl From<CallFailure> for CallError {
    fn from(failure: CallFailure) -> Self {
        let message = failure.message.into_string();
        match failure.kind {
            FailureKind::Panicked => CallError::Panicked { message },
            FailureKind::Returned => CallError::Returned { message },
        }
    }
}
