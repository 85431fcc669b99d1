//! [`PluginSlot`]: one loaded plugin, its origin and its status.

use std::path::PathBuf;

use onyx_plugin_api::host::{CallError, PluginInstance, PluginLibrary};
use onyx_plugin_api::{Event, PlatformEvent};

use super::{PluginStatus, Stage};
use crate::services::CallContext;
use crate::state::HostState;
use crate::watchdog::plugin_call::PluginCall;
use crate::watchdog::CallTag;

/// Where a plugin came from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PluginOrigin {
    /// Loaded from a library file: the file given, and the fresh copy actually opened.
    Library {
        /// The file the user named.
        path: PathBuf,
        /// The unique copy that was opened.
        loaded_from: PathBuf,
    },
    /// An in-process value (tests, embedding).
    InProcess,
}

/// A plugin the host calls each frame, until it faults.
pub struct PluginSlot {
    pub(crate) name: String,
    /// What the watchdog and the crash report call it.
    pub(crate) tag: &'static CallTag,
    pub(crate) origin: PluginOrigin,
    pub(crate) instance: PluginInstance,
    /// The library `instance` came from (`None` in-process), closed when it is replaced.
    pub(crate) library: Option<PluginLibrary>,
    pub(crate) status: PluginStatus,
    pub(crate) settings: Vec<(String, String)>,
    pub(crate) content_hash: Option<u64>,
    pub(crate) reloads: u32,
}

impl PluginSlot {
    /// The plugin's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Where it came from.
    pub fn origin(&self) -> &PluginOrigin {
        &self.origin
    }

    /// Running or faulted.
    pub fn status(&self) -> &PluginStatus {
        &self.status
    }

    /// How many times a new build replaced this plugin.
    pub fn reloads(&self) -> u32 {
        self.reloads
    }

    /// Calls `f` on the plugin unless it has faulted; on a panic or error, marks it faulted,
    /// logs it and queues a `PluginFaulted` platform event. Returns `None` if not called or
    /// failed.
    pub(crate) fn call<T>(
        &mut self,
        state: &mut HostState,
        stage: Stage,
        f: impl FnOnce(&mut PluginInstance, &mut CallContext<'_>) -> Result<T, CallError>,
    ) -> Option<T> {
        if self.status.is_faulted() {
            return None;
        }
        let start = std::time::Instant::now();
        let result = {
            let _call = PluginCall::enter(self.tag, stage);
            let mut cx = CallContext::new(state, &self.name);
            f(&mut self.instance, &mut cx)
        };
        (state.tools.diagnostics.timer).record(&self.name, stage, start.elapsed());
        let result = match state.io.flooded.take() {
            Some(flooder) if flooder == self.name => Err(CallError::Returned {
                message: format!(
                    "it sent more than {} custom events in one frame (the host setting \
                     `max_events_per_frame`); the rest were dropped",
                    state.io.max_events_per_frame
                ),
            }),
            other => {
                state.io.flooded = other;
                result
            }
        };
        match result {
            Ok(value) => Some(value),
            Err(error) => {
                self.fault(state, stage, &error);
                None
            }
        }
    }

    /// Drops the plugin object (inside its own image); a panic in its `Drop` faults the slot
    /// (stage `drop`) and is returned as the sentence that reports it.
    pub(crate) fn dispose(&mut self, state: &mut HostState) -> Option<String> {
        let disposed = {
            let _call = PluginCall::enter(self.tag, Stage::Drop);
            self.instance.dispose()
        };
        let error = disposed.err()?;
        self.fault(state, Stage::Drop, &error);
        match &self.status {
            PluginStatus::Faulted { message, .. } => {
                Some(format!("plugin `{}` faulted in drop: {message}", self.name))
            }
            PluginStatus::Running => None,
        }
    }

    pub(crate) fn fault(&mut self, state: &mut HostState, stage: Stage, error: &CallError) {
        let message = match error {
            CallError::Panicked { message } => format!("panicked: {message}"),
            CallError::Returned { message } => message.clone(),
        };
        tracing::error!(
            plugin = %self.name,
            %stage,
            "plugin `{}` faulted in {stage}: {message}; it will not be called again",
            self.name
        );
        state
            .io
            .events
            .push(Event::Platform(PlatformEvent::PluginFaulted {
                plugin: self.name.clone(),
                stage: stage.as_str().to_owned(),
                message: message.clone(),
            }));
        self.status = PluginStatus::Faulted { stage, message };
    }
}
