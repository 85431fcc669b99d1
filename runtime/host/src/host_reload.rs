//! Hot reload: replacing a running plugin with a new build of its library, keeping its state
//! and every entity.

use std::path::PathBuf;

use onyx_plugin_api::host::{CallError, PluginRequest};
use onyx_plugin_api::{AttachInfo, Event, PlatformEvent};

use crate::plugins::library_watcher::content_hash;
use crate::plugins::{
    open_library, LibraryWatcher, PluginOrigin, PluginStatus, ReloadError, Stage,
};
use crate::services::CallContext;
use crate::watchdog::plugin_call::PluginCall;
use crate::watchdog::CallTag;
use crate::Host;

fn message(error: &CallError) -> String {
    match error {
        CallError::Panicked { message } => format!("panicked: {message}"),
        CallError::Returned { message } => message.clone(),
    }
}

/// Drops a new build that will not be used, inside its own image; the sentence reporting a
/// panic in its `Drop`, if any.
fn discard(new: &mut onyx_plugin_api::host::PluginInstance, name: &str) -> Option<String> {
    let disposed = {
        let _call = PluginCall::enter(CallTag::plugin(name), Stage::Drop);
        new.dispose()
    };
    let error = disposed.err()?;
    let incident = format!(
        "the new build of plugin `{name}` failed while being dropped after a failed reload ({})",
        message(&error)
    );
    tracing::error!(plugin = name, "{incident}");
    Some(incident)
}

impl Host {
    /// Starts (or stops) watching every plugin loaded from a file: when a library is rebuilt,
    /// the plugin is reloaded at the start of the next frame.
    pub fn set_hot_reload(&mut self, enabled: bool) -> Result<(), notify::Error> {
        if !enabled {
            self.watcher = None;
            return Ok(());
        }
        let mut watcher = LibraryWatcher::new()?;
        for slot in &mut self.plugins {
            let PluginOrigin::Library { path, .. } = &slot.origin else {
                continue;
            };
            let hash = match slot.content_hash {
                Some(hash) => hash,
                None => content_hash(path).map_err(notify::Error::io)?,
            };
            slot.content_hash = Some(hash);
            watcher.watch(path, hash)?;
        }
        self.watcher = Some(watcher);
        Ok(())
    }

    /// Whether rebuilt libraries are reloaded automatically.
    pub fn hot_reload_enabled(&self) -> bool {
        self.watcher.is_some()
    }

    pub(crate) fn watch_new_plugin(&mut self, path: &std::path::Path, hash: Option<u64>) {
        if let (Some(watcher), Some(hash)) = (&mut self.watcher, hash) {
            if let Err(error) = watcher.watch(path, hash) {
                tracing::warn!(path = %path.display(), "cannot watch plugin file: {error}");
            }
        }
    }

    /// Reloads every library whose file was rebuilt (called at the start of each frame).
    pub(crate) fn poll_hot_reload(&mut self) {
        let Some(watcher) = &mut self.watcher else {
            return;
        };
        let changed = watcher.poll();
        for (path, hash) in changed {
            let names: Vec<String> = self
                .plugins
                .iter()
                .filter(|slot| matches!(&slot.origin, PluginOrigin::Library { path: p, .. } if std::path::absolute(p).ok().as_ref() == Some(&path)))
                .map(|slot| slot.name.clone())
                .collect();
            for name in names {
                tracing::info!(plugin = %name, path = %path.display(), "plugin file rebuilt; reloading");
                let _ = self.reload_with_hash(&name, Some(hash));
            }
        }
    }

    /// Reloads every plugin that was loaded from a file. Returns the errors, if any.
    pub fn reload_all(&mut self) -> Vec<ReloadError> {
        let names: Vec<String> = self
            .plugins
            .iter()
            .filter(|s| matches!(s.origin, PluginOrigin::Library { .. }))
            .map(|s| s.name.clone())
            .collect();
        names
            .iter()
            .filter_map(|name| self.reload_plugin(name).err())
            .collect()
    }

    /// Replaces plugin `name` with the build now in its library file.
    ///
    /// The new build is loaded from a fresh copy first; then old `save_state` → new
    /// `load_state` → old `on_detach` → new `on_attach` (with `reload: true`) → the old plugin
    /// object is dropped. The world is untouched. If anything before the swap fails, the old
    /// build keeps running; if the new `on_attach` fails, the old build is attached again.
    /// A faulted plugin is revived by a successful reload: its state is not carried over (it
    /// is not trusted), so the new build starts empty, gets `on_init` again (once the host
    /// has initialised its plugins) and the host logs that it did. The old image stays
    /// mapped (it is never unloaded; see [`open_library`]).
    pub fn reload_plugin(&mut self, name: &str) -> Result<(), ReloadError> {
        self.reload_with_hash(name, None)
    }

    /// [`Host::reload_plugin`], when the file's content hash is already known.
    fn reload_with_hash(&mut self, name: &str, hash: Option<u64>) -> Result<(), ReloadError> {
        let result = self.try_reload(name, hash);
        match &result {
            Ok(()) => {
                tracing::info!(plugin = name, "plugin reloaded");
                self.state
                    .io
                    .events
                    .push(Event::Platform(PlatformEvent::PluginReloaded {
                        plugin: name.to_owned(),
                    }));
            }
            Err(error) => {
                tracing::error!(plugin = name, "{error}; the previous build keeps running");
                self.state
                    .io
                    .events
                    .push(Event::Platform(PlatformEvent::PluginReloadFailed {
                        plugin: name.to_owned(),
                        message: error.to_string(),
                    }));
            }
        }
        result
    }

    fn try_reload(&mut self, name: &str, known_hash: Option<u64>) -> Result<(), ReloadError> {
        let index = self
            .plugins
            .iter()
            .position(|p| p.name == name)
            .ok_or_else(|| ReloadError::NotLoaded {
                plugin: name.to_owned(),
            })?;
        let PluginOrigin::Library { path, .. } = &self.plugins[index].origin else {
            return Err(ReloadError::NotFromFile {
                plugin: name.to_owned(),
            });
        };
        let path: PathBuf = path.clone();
        let hash = known_hash.or_else(|| content_hash(&path).ok());
        if let (Some(watcher), Some(hash)) = (&mut self.watcher, hash) {
            watcher.set_hash(&path, hash);
        }
        let step = |stage, which, error: &CallError| ReloadError::Step {
            plugin: name.to_owned(),
            stage,
            which,
            message: message(error),
        };

        // 1. Load and build the new version; nothing has changed yet.
        let (library, loaded_from) = open_library(&path).map_err(|cause| ReloadError::Load {
            plugin: name.to_owned(),
            cause: Box::new(cause),
        })?;
        if library.name() != name {
            return Err(ReloadError::NameChanged {
                plugin: name.to_owned(),
                found: library.name().to_owned(),
                path,
            });
        }
        let constructed = {
            let _call = PluginCall::enter(CallTag::plugin(name), Stage::Construct);
            library.instantiate()
        };
        let mut new = constructed.map_err(|e| step("constructor", "new", &e))?;

        // 2. Carry the state over (a faulted plugin's state is not trusted: start fresh). A
        //    panic on either side faults the plugin: the old build stays in place, not called
        //    again, and the run is no longer clean; an error returned just refuses the swap.
        let slot = &mut self.plugins[index];
        let was_running = !slot.status.is_faulted();
        if was_running {
            let carried = {
                let _call = PluginCall::enter(slot.tag, Stage::SaveState);
                slot.instance.save_state()
            }
            .map_err(|e| (Stage::SaveState, "old", e));
            let carried = carried.and_then(|state| {
                if state.is_empty() {
                    Ok(())
                } else {
                    let _call = PluginCall::enter(slot.tag, Stage::LoadState);
                    new.load_state(&state)
                        .map_err(|e| (Stage::LoadState, "new", e))
                }
            });
            if let Err((stage, which, error)) = carried {
                if let Some(incident) = discard(&mut new, name) {
                    self.incidents.push(incident);
                }
                let failed = step(stage.as_str(), which, &error);
                if matches!(error, CallError::Panicked { .. }) {
                    // The faulted status reports it (and makes the run unclean).
                    self.plugins[index].fault(&mut self.state, stage, &error);
                }
                return Err(failed);
            }
        }

        // 3. Swap: detach the old build, attach the new one.
        let info = AttachInfo {
            reload: true,
            settings: slot.settings.clone(),
        };
        slot.call(&mut self.state, Stage::Detach, |p, cx| p.on_detach(cx));
        // The new build registers its own scripts in `on_attach` (a build without one, or
        // from an older API, must not be asked to run the old build's scripts).
        self.state.tools.scripts.remove_plugin(&slot.name);
        let attached = {
            let _call = PluginCall::enter(slot.tag, Stage::Attach);
            let mut cx = CallContext::new(&mut self.state, &slot.name);
            new.on_attach(&mut cx, &info)
        };
        if let Err(error) = attached {
            if let Some(incident) = discard(&mut new, name) {
                self.incidents.push(incident);
            }
            if was_running {
                // Put the old build back, told it is being re-attached.
                let revived = {
                    let _call = PluginCall::enter(slot.tag, Stage::Attach);
                    let mut cx = CallContext::new(&mut self.state, &slot.name);
                    slot.instance.on_attach(&mut cx, &info)
                };
                if let Err(e) = revived {
                    slot.fault(&mut self.state, Stage::Attach, &e);
                } else {
                    slot.status = PluginStatus::Running;
                }
            }
            return Err(step("on_attach", "new", &error));
        }
        // The old plugin object is dropped here, inside its own image (which stays mapped).
        let mut old = std::mem::replace(&mut slot.instance, new);
        slot.status = PluginStatus::Running;
        let disposed = {
            let _call = PluginCall::enter(slot.tag, Stage::Drop);
            old.dispose()
        };
        if let Err(error) = disposed {
            let incident = format!(
                "the previous build of plugin `{name}` failed while being dropped after a \
                 reload ({}); the new build runs",
                message(&error)
            );
            tracing::error!(plugin = name, "{incident}");
            self.state
                .io
                .events
                .push(Event::Platform(PlatformEvent::Error {
                    message: incident.clone(),
                }));
            self.incidents.push(incident);
        }
        slot.origin = PluginOrigin::Library { path, loaded_from };
        slot.content_hash = hash;
        slot.reloads += 1;
        if !was_running {
            // Nothing came over from the faulted build: without `on_init` the new one would
            // sit idle, never having set itself up.
            tracing::warn!(
                plugin = name,
                "plugin revived by a good build after its fault, with empty state (the \
                 faulted build's state is not carried over); calling its on_init again"
            );
            if self.initialized {
                slot.call(&mut self.state, Stage::Init, |p, cx| p.on_init(cx));
            }
        }
        // The new image builds a fresh egui context: its textures start over.
        self.gui.forget(name);
        Ok(())
    }

    /// Carries out the plugin changes plugins asked for during the frame.
    pub(crate) fn apply_plugin_requests(&mut self) {
        let requests = std::mem::take(&mut self.state.io.plugin_requests);
        for request in requests {
            match request {
                PluginRequest::Reload(name) => {
                    let _ = self.reload_plugin(&name);
                }
                PluginRequest::ReloadAll => {
                    let _ = self.reload_all();
                }
                PluginRequest::Load(spec) => {
                    if let Err(error) = self.load_plugin(&spec) {
                        tracing::error!("{error}");
                    }
                }
                PluginRequest::Unload(name) => {
                    if !self.unload_plugin(&name) {
                        tracing::warn!(plugin = %name, "asked to unload a plugin that is not loaded");
                    }
                }
            }
        }
    }
}
