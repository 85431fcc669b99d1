//! Frame diagnostics for tools: what the last frame cost.
//!
//! - `stage_timer.rs`: [`StageTimer`], time per plugin per lifecycle method (an `Instant`
//!   pair per call).
//! - `frame_diagnostics.rs`: [`FrameDiagnostics`], the figures of the frame being run and of
//!   the last complete one.

mod frame_diagnostics;
mod stage_timer;

pub use frame_diagnostics::FrameDiagnostics;
pub use stage_timer::StageTimer;
