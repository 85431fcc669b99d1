//! The console: every `tracing` record of the process (host, renderer, physics, plugins)
//! kept in a bounded ring buffer that tools read incrementally (`Ctx::log_lines_since`).
//!
//! - `console_log.rs`: [`ConsoleLog`], the ring buffer, and [`console_log`], the process's.
//! - `console_layer.rs`: [`ConsoleLayer`], the `tracing_subscriber` layer that fills it.
//! - `event_trace.rs`: [`trace_errors`], error events of physics and rendering into the log.

mod console_layer;
mod console_log;
mod event_trace;

pub use console_layer::ConsoleLayer;
pub use console_log::{console_log, ConsoleLog, CONSOLE_CAPACITY};
pub use event_trace::trace_errors;

use tracing_subscriber::layer::SubscriberExt;

/// Makes the console capture records at `INFO` and above when nobody has installed a global
/// `tracing` subscriber yet (a `HeadlessHost` in a test, a program
/// embedding the runtime). The `onyx` binary installs [`ConsoleLayer`] in its own subscriber.
pub fn install_default() {
    if tracing::dispatcher::has_been_set() {
        return;
    }
    let subscriber = tracing_subscriber::registry()
        .with(tracing_subscriber::filter::LevelFilter::INFO)
        .with(ConsoleLayer);
    // Another thread may have won the race; either way a subscriber is installed.
    let _ = tracing::subscriber::set_global_default(subscriber);
}
