//! [`ReloadReport`]: what one hot swap did and where its time went.

use std::time::Duration;

use super::{ImageFate, LoadTimings};

/// One successful swap, stage by stage ([`Host::last_reload`](crate::Host::last_reload)).
#[derive(Clone, Debug)]
pub struct ReloadReport {
    /// The plugin swapped.
    pub plugin: String,
    /// Reading, checking, copying and mapping the new build.
    pub load: LoadTimings,
    /// The new build's constructor.
    pub construct: Duration,
    /// Old `save_state` and new `load_state`.
    pub state: Duration,
    /// Bytes of state carried over.
    pub state_bytes: usize,
    /// Old `on_detach` and new `on_attach`.
    pub attach: Duration,
    /// Dropping the old plugin object (inside its image).
    pub drop: Duration,
    /// Handing the old image back to the system loader (for an automatic reload, done at the
    /// end of the frame and not part of `total`).
    pub unload: Duration,
    /// The whole swap.
    pub total: Duration,
    /// What became of the old build's image.
    pub old_image: ImageFate,
}
