//! [`FrameDiagnostics`]: the figures of the current frame and of the last complete one.

use std::time::{Duration, Instant};

use onyx_plugin_api::tools::Diagnostics;

use super::StageTimer;

/// What the host measures while running frames; tools read [`FrameDiagnostics::last`].
#[derive(Debug, Default)]
pub struct FrameDiagnostics {
    /// The last complete frame.
    pub last: Diagnostics,
    /// Plugin call times of the frame being run.
    pub timer: StageTimer,
    /// Physics time of the frame being run.
    pub physics: Duration,
    /// When the frame being run started.
    pub frame_start: Option<Instant>,
    previous_start: Option<Instant>,
}

impl FrameDiagnostics {
    /// Marks the start of a frame.
    pub fn begin_frame(&mut self) {
        let now = Instant::now();
        self.previous_start = self.frame_start.replace(now);
        self.physics = Duration::ZERO;
    }

    /// Milliseconds since [`FrameDiagnostics::begin_frame`], and between the last two starts.
    pub fn frame_times_ms(&self) -> (f64, f64) {
        let Some(start) = self.frame_start else {
            return (0.0, 0.0);
        };
        let interval = self
            .previous_start
            .map_or(0.0, |p| (start - p).as_secs_f64() * 1000.0);
        (start.elapsed().as_secs_f64() * 1000.0, interval)
    }
}
