//! Hot reload: replacing a running plugin with a new build of its library, keeping its state
//! and every entity.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use onyx_plugin_api::host::{CallError, PluginLibrary, PluginRequest};
use onyx_plugin_api::{AttachInfo, Event, PlatformEvent};

use crate::plugins::{
    content_hash, open_library_bytes, read_library, unload_image, ImageFate, LibraryBytes,
    LibraryWatcher, PluginLoadError, PluginOrigin, PluginStatus, ReloadError, ReloadGate,
    ReloadReport, RetiredImage, Stage,
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

/// A new build read from disk, ready to replace a running plugin.
struct NewBuild {
    path: PathBuf,
    bytes: LibraryBytes,
    hash: u64,
    read: Duration,
}

impl NewBuild {
    fn read(path: &Path) -> Result<Self, PluginLoadError> {
        let started = Instant::now();
        let bytes = read_library(path)?;
        let hash = content_hash(&bytes);
        Ok(Self {
            path: path.to_path_buf(),
            bytes,
            hash,
            read: started.elapsed(),
        })
    }
}

/// When a swap hands the old build's image back to the system loader.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Unload {
    /// Before the swap returns (a reload asked for by a call: the caller sees the outcome).
    Now,
    /// At the end of the frame (an automatic reload at the start of one).
    AfterFrame,
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
        for slot in &self.plugins {
            if let PluginOrigin::Library { path, .. } = &slot.origin {
                watcher.watch(path)?;
            }
        }
        self.watcher = Some(watcher);
        Ok(())
    }

    /// Whether rebuilt libraries are reloaded automatically.
    pub fn hot_reload_enabled(&self) -> bool {
        self.watcher.is_some()
    }

    /// The handle that holds automatic reloads while builds run and releases a round of
    /// rebuilt libraries to be swapped in one frame (see [`ReloadGate`]).
    pub fn reload_gate(&self) -> ReloadGate {
        self.reload_gate.clone()
    }

    /// The last successful swap, stage by stage.
    pub fn last_reload(&self) -> Option<&ReloadReport> {
        self.last_reload.as_ref()
    }

    pub(crate) fn watch_new_plugin(&mut self, path: &Path) {
        if let Some(watcher) = &mut self.watcher {
            if let Err(error) = watcher.watch(path) {
                tracing::warn!(path = %path.display(), "cannot watch plugin file: {error}");
            }
        }
    }

    /// Swaps every plugin whose library was rebuilt (called at the start of each frame):
    /// all the libraries that are ready swap in this one frame, unless the reload gate holds
    /// them for a build round still running.
    pub(crate) fn poll_hot_reload(&mut self) {
        let Some(watcher) = &mut self.watcher else {
            return;
        };
        let ready = watcher.poll();
        let (held, released) = self.reload_gate.take();
        for path in &released {
            watcher.settle(path);
        }
        for path in ready.into_iter().chain(released.iter().cloned()) {
            if !self.pending_reloads.contains(&path) {
                self.pending_reloads.push(path);
            }
        }
        if held && released.is_empty() {
            return;
        }
        let paths = std::mem::take(&mut self.pending_reloads);
        let mut batch = Vec::new();
        for path in paths {
            for name in self.plugins_from(&path) {
                match NewBuild::read(&path) {
                    Ok(build) if Some(build.hash) == self.loaded_hash(&name) => {
                        tracing::debug!(plugin = %name, "library rewritten with the same content; not reloaded");
                    }
                    Ok(build) => {
                        tracing::info!(plugin = %name, path = %path.display(), "plugin library rebuilt; reloading");
                        batch.push((name, Some(build)));
                    }
                    // Read again by the reload, which reports why it failed.
                    Err(_) => batch.push((name, None)),
                }
            }
        }
        // Swapped at the start of the frame; the old images go at its end, so the new
        // builds run this frame without waiting for the loader to unmap the old ones.
        let _ = self.swap_all(batch, Unload::AfterFrame);
    }

    /// The plugins loaded from `path`.
    fn plugins_from(&self, path: &Path) -> Vec<String> {
        let wanted = std::path::absolute(path).ok();
        self.plugins
            .iter()
            .filter(|slot| matches!(&slot.origin, PluginOrigin::Library { path: p, .. } if std::path::absolute(p).ok() == wanted))
            .map(|slot| slot.name.clone())
            .collect()
    }

    fn loaded_hash(&self, name: &str) -> Option<u64> {
        self.plugin(name).and_then(|slot| slot.content_hash)
    }

    /// Swaps every plugin whose library file changed since it was loaded (and every faulted
    /// one, to revive it), all in this one call — between two frames. A plugin whose file is
    /// unchanged is left alone. Returns the errors, if any; each refused plugin keeps its
    /// running build, the others swap.
    pub fn reload_all(&mut self) -> Vec<ReloadError> {
        let mut batch = Vec::new();
        let mut errors = Vec::new();
        let library_plugins: Vec<(String, PathBuf, bool)> = self
            .plugins
            .iter()
            .filter_map(|slot| match &slot.origin {
                PluginOrigin::Library { path, .. } => {
                    Some((slot.name.clone(), path.clone(), slot.status.is_faulted()))
                }
                PluginOrigin::InProcess => None,
            })
            .collect();
        for (name, path, faulted) in library_plugins {
            match NewBuild::read(&path) {
                Ok(build) if !faulted && Some(build.hash) == self.loaded_hash(&name) => {}
                Ok(build) => batch.push((name, Some(build))),
                Err(cause) => {
                    let error = ReloadError::Load {
                        plugin: name.clone(),
                        cause: Box::new(cause),
                    };
                    self.report_reload(&name, Err(&error));
                    errors.push(error);
                }
            }
        }
        errors.extend(self.swap_all(batch, Unload::Now));
        errors
    }

    /// Swaps each plugin of `batch` for its new build (read again when `None`), one after
    /// the other with no plugin call in between.
    fn swap_all(
        &mut self,
        batch: Vec<(String, Option<NewBuild>)>,
        unload: Unload,
    ) -> Vec<ReloadError> {
        let count = batch.len();
        let mut errors = Vec::new();
        for (name, build) in batch {
            if let Err(error) = self.reload_from(&name, build, unload) {
                errors.push(error);
            }
        }
        if count > 1 {
            tracing::info!(
                "{} of {count} rebuilt plugins swapped in one frame",
                count - errors.len()
            );
        }
        errors
    }

    /// Replaces plugin `name` with the build now in its library file.
    ///
    /// The new build is read once and loaded from a fresh copy first; then old `save_state`
    /// → new `load_state` → old `on_detach` → new `on_attach` (with `reload: true`) → the
    /// old plugin object is dropped inside its image, and the image is handed back to the
    /// system loader once nothing from it can run (see `plugins/image_unload.rs`). The world
    /// is untouched. If anything before the swap fails — the new build cannot be loaded, or
    /// cannot read the running build's state — the old build keeps running untouched; if the
    /// new `on_attach` fails, the old build is attached again. A faulted plugin is revived
    /// by a successful reload: its state is not carried over (it is not trusted), so the new
    /// build starts empty, gets `on_init` again (once the host has initialised its plugins)
    /// and the host logs that it did.
    pub fn reload_plugin(&mut self, name: &str) -> Result<(), ReloadError> {
        self.reload_from(name, None, Unload::Now)
    }

    /// [`Host::reload_plugin`] with the new build's bytes, if already read; reports the
    /// outcome (log and platform event).
    fn reload_from(
        &mut self,
        name: &str,
        build: Option<NewBuild>,
        unload: Unload,
    ) -> Result<(), ReloadError> {
        if unload == Unload::Now {
            // Images retired earlier go first, in order.
            self.unload_retired_images();
        }
        let result = self.try_reload(name, build, unload);
        self.report_reload(name, result.as_ref().map(|_| ()));
        result
    }

    fn report_reload(&mut self, name: &str, result: Result<(), &ReloadError>) {
        match result {
            Ok(()) => {
                if let Some(report) = &self.last_reload {
                    tracing::info!(
                        plugin = name,
                        total = ?report.total,
                        old_image = %report.old_image,
                        "plugin reloaded"
                    );
                }
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
    }

    /// Closes a build that will not run (or no longer runs): its object is already dropped.
    fn unload(&self, name: &str, library: PluginLibrary, loaded_from: &Path) -> ImageFate {
        let fate = unload_image(library, loaded_from, self.keep_old_builds);
        tracing::debug!(plugin = name, "old image {fate}");
        fate
    }

    /// Hands back the images of builds swapped out by this frame's automatic reloads, and
    /// completes the swap reports that waited for them.
    pub(crate) fn unload_retired_images(&mut self) {
        for retired in std::mem::take(&mut self.retired_images) {
            let started = Instant::now();
            let fate = self.unload(&retired.name, retired.library, &retired.loaded_from);
            let took = started.elapsed();
            if let Some(report) = &mut self.last_reload {
                if report.plugin == retired.name && report.old_image == ImageFate::AfterFrame {
                    report.old_image = fate;
                    report.unload = took;
                }
            }
        }
    }

    fn try_reload(
        &mut self,
        name: &str,
        build: Option<NewBuild>,
        unload: Unload,
    ) -> Result<(), ReloadError> {
        let started = Instant::now();
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
        let load_error = |cause| ReloadError::Load {
            plugin: name.to_owned(),
            cause: Box::new(cause),
        };
        let build = match build {
            Some(build) => build,
            None => NewBuild::read(path).map_err(load_error)?,
        };
        if let Some(watcher) = &mut self.watcher {
            watcher.settle(&build.path);
        }
        let step = |stage, which, error: &CallError| ReloadError::Step {
            plugin: name.to_owned(),
            stage,
            which,
            message: message(error),
        };

        // 1. Load and build the new version; nothing has changed yet.
        let opened = open_library_bytes(&build.path, &build.bytes, build.hash, build.read)
            .map_err(load_error)?;
        drop(build.bytes);
        let library = opened.library;
        if library.name() != name {
            let found = library.name().to_owned();
            self.unload(name, library, &opened.loaded_from);
            return Err(ReloadError::NameChanged {
                plugin: name.to_owned(),
                found,
                path: build.path,
            });
        }
        let construct_started = Instant::now();
        let constructed = {
            let _call = PluginCall::enter(CallTag::plugin(name), Stage::Construct);
            library.instantiate()
        };
        let mut new = match constructed {
            Ok(new) => new,
            Err(error) => {
                self.unload(name, library, &opened.loaded_from);
                return Err(step("constructor", "new", &error));
            }
        };
        let construct = construct_started.elapsed();

        // 2. Carry the state over (a faulted plugin's state is not trusted: start fresh). A
        //    panic on either side faults the plugin: the old build stays in place, not called
        //    again, and the run is no longer clean; an error returned just refuses the swap.
        let state_started = Instant::now();
        let mut state_bytes = 0;
        let slot = &mut self.plugins[index];
        let was_running = !slot.status.is_faulted();
        if was_running {
            let carried = {
                let _call = PluginCall::enter(slot.tag, Stage::SaveState);
                slot.instance.save_state()
            }
            .map_err(|e| (Stage::SaveState, "old", e));
            let carried = carried.and_then(|state| {
                state_bytes = state.len();
                if state.is_empty() {
                    Ok(())
                } else {
                    let _call = PluginCall::enter(slot.tag, Stage::LoadState);
                    new.load_state(&state)
                        .map_err(|e| (Stage::LoadState, "new", e))
                }
            });
            if let Err((stage, which, error)) = carried {
                let clean = match discard(&mut new, name) {
                    Some(incident) => {
                        self.incidents.push(incident);
                        false
                    }
                    None => true,
                };
                drop(new);
                if clean {
                    self.unload(name, library, &opened.loaded_from);
                }
                let failed = match (&error, stage) {
                    (CallError::Returned { message }, Stage::LoadState) => {
                        ReloadError::StateRefused {
                            plugin: name.to_owned(),
                            message: message.clone(),
                        }
                    }
                    _ => step(stage.as_str(), which, &error),
                };
                if matches!(error, CallError::Panicked { .. }) {
                    // The faulted status reports it (and makes the run unclean).
                    self.plugins[index].fault(&mut self.state, stage, &error);
                }
                return Err(failed);
            }
        }
        let state = state_started.elapsed();

        // 3. Swap: detach the old build, attach the new one.
        let attach_started = Instant::now();
        let slot = &mut self.plugins[index];
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
            let incident = discard(&mut new, name);
            drop(new);
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
            // The new build's `on_attach` may have started anything before it failed: its
            // image stays mapped.
            drop(library);
            if let Some(incident) = incident {
                self.incidents.push(incident);
            }
            return Err(step("on_attach", "new", &error));
        }
        let attach = attach_started.elapsed();

        // 4. The old plugin object is dropped inside its own image, then the image goes.
        let drop_started = Instant::now();
        let mut old = std::mem::replace(&mut slot.instance, new);
        let old_library = slot.library.replace(library);
        let old_origin = std::mem::replace(
            &mut slot.origin,
            PluginOrigin::Library {
                path: build.path,
                loaded_from: opened.loaded_from,
            },
        );
        slot.status = PluginStatus::Running;
        slot.content_hash = Some(opened.content_hash);
        slot.reloads += 1;
        let disposed = {
            let _call = PluginCall::enter(slot.tag, Stage::Drop);
            old.dispose()
        };
        drop(old);
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
        let dropped = drop_started.elapsed();
        let unload_started = Instant::now();
        let old_image = match disposed {
            Ok(()) => match (old_library, &old_origin) {
                (Some(library), PluginOrigin::Library { loaded_from, .. }) => match unload {
                    Unload::Now => self.unload(name, library, loaded_from),
                    Unload::AfterFrame => {
                        self.retired_images.push(RetiredImage {
                            name: name.to_owned(),
                            library,
                            loaded_from: loaded_from.clone(),
                        });
                        ImageFate::AfterFrame
                    }
                },
                _ => ImageFate::Kept("it was not loaded from a file".into()),
            },
            Err(error) => {
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
                ImageFate::Kept("its plugin object panicked while being dropped".into())
            }
        };
        self.last_reload = Some(ReloadReport {
            plugin: name.to_owned(),
            load: opened.timings,
            construct,
            state,
            state_bytes,
            attach,
            drop: dropped,
            unload: unload_started.elapsed(),
            total: started.elapsed(),
            old_image,
        });
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
