//! [`PlayCommand`]: what a tool asks of the play session.

/// A change to the play session ([`Ctx::play`](crate::Ctx::play), …).
#[repr(u8)]
#[derive(abi_stable::StableAbi, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PlayCommand {
    /// From Edit: snapshot the world and run. From Paused: resume.
    Play,
    /// Stop fixed steps and scripts, keeping the session.
    Pause,
    /// While paused (or editing: first pausing), run exactly one fixed step.
    Step,
    /// End the session and put the world back as it was at Play.
    Stop,
}
