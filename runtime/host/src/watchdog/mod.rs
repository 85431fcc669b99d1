//! What the host can only report, not prevent: plugin calls that do not return, and native
//! failures that end the process.
//!
//! - `plugin_call.rs`: [`PluginCall`](plugin_call) marks which plugin and stage each thread
//!   is running, where a thread or a signal handler can read it without locks.
//! - `watchdog_thread.rs`: [`start`] a thread that reports calls running past a limit.
//! - `crash_report.rs`: [`install_crash_report`] — one line naming the plugin and stage on a
//!   segfault, abort, stack overflow or `exit` from a plugin, and a distinct exit status.
//!
//! The host marks every call into a plugin; the watchdog and the crash handlers are
//! process-wide and started by the binary that owns the process (`onyx`).

mod crash_report;
pub(crate) mod plugin_call;
mod watchdog_thread;

pub use crash_report::{install_crash_report, EXIT_NATIVE_CRASH, EXIT_PLUGIN_EXITED};
pub use plugin_call::CallTag;
pub use watchdog_thread::{
    debugger_attached, set_stuck_sink, start, StuckSink, WatchdogSettings, DEFAULT_WATCHDOG_LIMIT,
};
