//! [`Flow`]: what a plugin wants the host to do after `on_update`.

use abi_stable::StableAbi;

/// Returned by [`Plugin::on_update`](crate::Plugin::on_update).
#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Flow {
    /// Keep running.
    #[default]
    Continue,
    /// Finish this frame, detach every plugin and exit cleanly.
    Quit,
}
