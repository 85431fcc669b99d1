//! [`Time`]: the host clock as a plugin sees it.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

/// The host clock at the moment of a lifecycle call. All durations are in seconds.
///
/// The host runs a fixed-step loop: each frame, scaled real time is added to an accumulator
/// and [`Plugin::on_fixed_update`](crate::Plugin::on_fixed_update) runs once per whole
/// `fixed_delta` in it (0..N times, capped). Rendering then uses `alpha` to interpolate
/// between the last two fixed states.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Time {
    /// Scaled time of the current frame, seconds (0 while paused).
    pub delta: f32,
    /// Length of one fixed step, seconds (1/60 by default).
    pub fixed_delta: f32,
    /// Scaled time since the host started, seconds.
    pub total: f64,
    /// Fixed steps run since the host started.
    pub ticks: u64,
    /// Frames run since the host started.
    pub frame: u64,
    /// Fixed steps run in the current frame.
    pub fixed_steps_this_frame: u32,
    /// Fraction of a fixed step left in the accumulator, in `[0, 1)`: the interpolation
    /// factor between the previous and the current fixed state.
    pub alpha: f32,
    /// Multiplier applied to real time (1 = real time).
    pub time_scale: f32,
    /// Whether the simulation is paused (fixed steps only run when single-stepped).
    pub paused: bool,
}
