//! [`ConsoleLayer`]: turns `tracing` events into console lines.

use std::fmt::Write as _;
use std::time::{SystemTime, UNIX_EPOCH};

use onyx_plugin_api::tools::LogLine;
use tracing::field::{Field, Visit};
use tracing::{Event, Subscriber};
use tracing_subscriber::layer::Context;
use tracing_subscriber::Layer;

use super::console_log;

/// The target of the records a plugin logs through `Ctx::log` (with a `plugin` field).
const PLUGIN_TARGET: &str = "onyx::plugin";

/// A `tracing_subscriber` layer writing every event it sees into [`console_log`]. Plugin logs
/// (target `onyx::plugin`, field `plugin`) are attributed to the plugin; other records to
/// their target, with any `plugin` field kept in the message.
#[derive(Clone, Copy, Debug, Default)]
pub struct ConsoleLayer;

#[derive(Default)]
struct Fields {
    message: String,
    plugin: Option<String>,
    rest: String,
}

impl Visit for Fields {
    fn record_str(&mut self, field: &Field, value: &str) {
        match field.name() {
            "message" => self.message.push_str(value),
            "plugin" => self.plugin = Some(value.to_owned()),
            name => {
                let _ = write!(self.rest, " {name}={value}");
            }
        }
    }

    fn record_debug(&mut self, field: &Field, value: &dyn std::fmt::Debug) {
        match field.name() {
            "message" => {
                let _ = write!(self.message, "{value:?}");
            }
            "plugin" => self.plugin = Some(format!("{value:?}")),
            name => {
                let _ = write!(self.rest, " {name}={value:?}");
            }
        }
    }
}

impl<S: Subscriber> Layer<S> for ConsoleLayer {
    fn on_event(&self, event: &Event<'_>, _ctx: Context<'_, S>) {
        let mut fields = Fields::default();
        event.record(&mut fields);
        let metadata = event.metadata();
        let source = match fields.plugin {
            Some(plugin) if metadata.target() == PLUGIN_TARGET => plugin,
            Some(plugin) => {
                fields.rest.insert_str(0, &format!(" plugin={plugin}"));
                metadata.target().to_owned()
            }
            None => metadata.target().to_owned(),
        };
        let unix_ms = SystemTime::now()
            .duration_since(UNIX_EPOCH)
            .map_or(0, |d| d.as_millis() as u64);
        console_log().push(LogLine {
            seq: 0,
            unix_ms,
            level: metadata.level().to_string(),
            source,
            message: fields.message + &fields.rest,
        });
    }
}
