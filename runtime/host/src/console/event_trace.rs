//! [`trace_errors`]: puts the error events a subsystem raised into the log (and so the
//! console), for subsystems that report errors only as events.

use onyx_plugin_api::{Event, GraphicsEvent, PlatformEvent};

/// Logs the error events among `events` (raised by `subsystem`: `physics`, `render`) at
/// error level, target `onyx::<subsystem>`.
pub fn trace_errors(subsystem: &str, events: &[Event]) {
    for event in events {
        match event {
            Event::Platform(PlatformEvent::Error { message }) => {
                tracing::error!(target: "onyx::events", subsystem, "{message}");
            }
            Event::Graphics(GraphicsEvent::AssetFailed { path, message }) => {
                tracing::error!(target: "onyx::events", subsystem, path = %path, "{message}");
            }
            _ => {}
        }
    }
}
