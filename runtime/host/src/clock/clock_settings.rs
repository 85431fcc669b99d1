//! [`ClockSettings`]: the tunables of the fixed-step loop.

/// Settings of the host's fixed-step clock.
#[derive(Clone, Debug, PartialEq)]
pub struct ClockSettings {
    /// Fixed steps per second. Default 60. Higher: smoother, more accurate simulation, more
    /// CPU per second of play. Lower: cheaper, coarser. Must be finite and > 0.
    pub fixed_hz: f64,
    /// Most fixed steps run in one frame. Default 8. When a frame took longer than
    /// `max_steps_per_frame / fixed_hz` seconds, the excess time is dropped (the game slows
    /// down) instead of running ever more steps per frame — the "spiral of death" guard.
    /// Too low: the game slows on every hitch. Too high: one slow frame snowballs.
    pub max_steps_per_frame: u32,
    /// Longest real frame time accepted, seconds. Default 0.25. A longer frame (a breakpoint,
    /// a dragged window) counts as this long.
    pub max_frame_time: f64,
    /// Multiplier on real time. Default 1. 0 stops time without pausing; must be finite, ≥ 0.
    pub time_scale: f32,
}

impl Default for ClockSettings {
    fn default() -> Self {
        Self {
            fixed_hz: 60.0,
            max_steps_per_frame: 8,
            max_frame_time: 0.25,
            time_scale: 1.0,
        }
    }
}
