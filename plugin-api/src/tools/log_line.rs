//! [`LogLine`]: one line of the host's console.

use serde::{Deserialize, Serialize};

/// One log record captured by the host (its own, the renderer's, physics', and every
/// plugin's `ctx.info(..)`), as [`Ctx::log_lines_since`](crate::Ctx::log_lines_since) returns it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct LogLine {
    /// Sequence number, increasing by one per line since the process started.
    pub seq: u64,
    /// Milliseconds since the UNIX epoch.
    pub unix_ms: u64,
    /// `TRACE`, `DEBUG`, `INFO`, `WARN` or `ERROR`.
    pub level: String,
    /// Who logged it: the plugin's name for plugin logs, else the `tracing` target
    /// (`onyx_render::gpu_context`, …).
    pub source: String,
    /// The message, with the record's other fields appended as `key=value`.
    pub message: String,
}
