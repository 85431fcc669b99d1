//! [`ReloadGate`]: holds automatic hot reloads while builds run, then releases them as one
//! batch.

use std::path::PathBuf;
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};

/// A handle another thread uses to time a host's automatic reloads (`onyx dev` drives it
/// from its build rounds: one edit rebuilds every plugin depending on the edited crate, and
/// they must all change in the same frame).
///
/// While held, rebuilt libraries the watcher notices wait. [`ReloadGate::release`] names the
/// libraries a round rebuilt: at the start of the next frame the host swaps, in that one
/// frame, every one of them (and every waiting one) whose content differs from what runs.
#[derive(Clone, Debug, Default)]
pub struct ReloadGate(Arc<Mutex<GateState>>);

#[derive(Debug, Default)]
struct GateState {
    held: bool,
    released: Vec<PathBuf>,
}

impl ReloadGate {
    fn lock(&self) -> MutexGuard<'_, GateState> {
        self.0.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// Builds are running: swap nothing the watcher notices until [`ReloadGate::release`].
    pub fn hold(&self) {
        self.lock().held = true;
    }

    /// The builds are done and `libraries` are complete: swap every changed one, and every
    /// library that waited, in the next frame.
    pub fn release(&self, libraries: impl IntoIterator<Item = PathBuf>) {
        let mut state = self.lock();
        state.held = false;
        state.released.extend(libraries);
    }

    /// Whether the gate is held, and the libraries released since the last call.
    pub(crate) fn take(&self) -> (bool, Vec<PathBuf>) {
        let mut state = self.lock();
        (state.held, std::mem::take(&mut state.released))
    }
}
