//! [`PlayMode`]: whether the simulation runs.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

/// The editor's play state. A host starts in `Playing` (applications simply run); an editor
/// calls [`Ctx::stop`](crate::Ctx::stop) to edit.
#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum PlayMode {
    /// Editing: no fixed steps (no physics), scripts do not run.
    Edit,
    /// Running: fixed steps and scripts.
    #[default]
    Playing,
    /// Paused inside a play session: [`Ctx::step`](crate::Ctx::step) runs one fixed step.
    Paused,
}
