//! [`PlaySession`]: the play mode, the snapshot taken at Play, and a pending restore.

use onyx_plugin_api::host::PlayCommand;
use onyx_plugin_api::PlayMode;

use super::WorldSnapshot;
use crate::clock::FixedClock;

/// The editor's play state. Commands change the mode and the clock at once; putting the
/// world back (which must not happen in the middle of a plugin call) waits for the end of
/// the frame: [`PlaySession::take_restore`].
#[derive(Debug, Default)]
pub struct PlaySession {
    mode: PlayMode,
    snapshot: Option<WorldSnapshot>,
    restore: Option<WorldSnapshot>,
}

impl PlaySession {
    /// The current mode.
    pub fn mode(&self) -> PlayMode {
        self.mode
    }

    /// Applies `command`: `world` is snapshot on Play from Edit; the clock is paused in
    /// Edit and Paused.
    pub fn command(&mut self, command: PlayCommand, world: &hecs::World, clock: &mut FixedClock) {
        match (command, self.mode) {
            (PlayCommand::Play, PlayMode::Edit) => {
                self.snapshot = Some(WorldSnapshot::capture(world));
                self.mode = PlayMode::Playing;
            }
            (PlayCommand::Play, _) => self.mode = PlayMode::Playing,
            (PlayCommand::Pause, PlayMode::Edit) => {}
            (PlayCommand::Pause, _) => self.mode = PlayMode::Paused,
            (PlayCommand::Step, PlayMode::Edit) => {
                self.snapshot = Some(WorldSnapshot::capture(world));
                self.mode = PlayMode::Paused;
                clock.step_once();
            }
            (PlayCommand::Step, _) => {
                self.mode = PlayMode::Paused;
                clock.step_once();
            }
            (PlayCommand::Stop, _) => {
                self.mode = PlayMode::Edit;
                self.restore = self.snapshot.take();
            }
        }
        clock.set_paused(self.mode != PlayMode::Playing);
        tracing::info!(?command, mode = ?self.mode, "play mode");
    }

    /// The snapshot to put back after a Stop, once.
    pub fn take_restore(&mut self) -> Option<WorldSnapshot> {
        self.restore.take()
    }

    /// Forgets the snapshot (the world was replaced by a scene: Stop has nothing to restore).
    pub fn forget_snapshot(&mut self) {
        self.snapshot = None;
        self.restore = None;
    }
}
