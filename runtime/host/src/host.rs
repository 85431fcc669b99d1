//! [`Host`]: the world, the clock, the event dispatcher and the plugins, one frame at a time.

use std::path::Path;

use onyx_plugin_api::host::{PluginInstance, PluginLibrary};
use onyx_plugin_api::{AttachInfo, Event, Flow, PlatformEvent, Plugin, Time, WindowEvent};

use crate::clock::FixedClock;
use crate::plugins::plugin_search::looks_like_path;
use crate::plugins::{
    open_library, PluginLoadError, PluginOrigin, PluginSearchPath, PluginSlot, PluginStatus, Stage,
};
use crate::scene::{self, SceneError};
use crate::state::HostState;
use crate::state_dump::dump_state;
use crate::watchdog::plugin_call::PluginCall;
use crate::watchdog::CallTag;
use crate::HostConfig;

/// Longest a screenshot ([`Host::render_image`]) waits for the models and textures it draws
/// to finish loading.
pub const SCREENSHOT_LOAD_TIMEOUT: std::time::Duration = std::time::Duration::from_secs(120);

/// What one frame did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameReport {
    /// Fixed steps run.
    pub fixed_steps: u32,
    /// Whether a plugin or the window asked to quit.
    pub quit: bool,
}

/// The host runtime without a window: drive it with [`Host::frame`]. The windowed runner and
/// [`HeadlessHost`](crate::HeadlessHost) both wrap one.
///
/// Each frame, in order: pending events are folded into the input state and dispatched
/// (`on_event`, plus `on_resize` for resizes) → `on_fixed_update` once per fixed step →
/// `on_update` → scripts (`on_script`) → `on_render` → `draw_gui`. Plugins are called in
/// load order; `on_detach` runs in reverse load order at [`Host::shutdown`].
pub struct Host {
    pub(crate) state: HostState,
    pub(crate) plugins: Vec<PluginSlot>,
    plugin_settings: Vec<(String, String, String)>,
    search_path: PluginSearchPath,
    pub(crate) initialized: bool,
    shut_down: bool,
    pub(crate) watcher: Option<crate::plugins::LibraryWatcher>,
    /// Times automatic reloads (`onyx dev` holds them while a build round runs).
    pub(crate) reload_gate: crate::plugins::ReloadGate,
    /// Rebuilt libraries noticed while the gate was held.
    pub(crate) pending_reloads: Vec<std::path::PathBuf>,
    /// The last successful swap, stage by stage.
    pub(crate) last_reload: Option<crate::plugins::ReloadReport>,
    /// Old builds' images swapped out by this frame's automatic reloads, handed back to the
    /// system loader at the end of the frame (`Host::unload_retired_images`).
    pub(crate) retired_images: Vec<crate::plugins::RetiredImage>,
    /// Keep old builds' images mapped ([`HostConfig::keep_old_builds`]).
    pub(crate) keep_old_builds: bool,
    pub(crate) gui: crate::gui::GuiSystem,
    /// What made the run unclean besides a faulted plugin still loaded (a plugin that
    /// panicked while being dropped, or whose state could not be carried over).
    pub(crate) incidents: Vec<String>,
}

impl Host {
    /// A host with an empty world.
    pub fn new(config: HostConfig) -> Self {
        let mut state = HostState::new(
            FixedClock::new(config.clock),
            crate::assets::AssetRegistry::new(config.asset_root),
        );
        state.io.max_events_per_frame = config.max_events_per_frame;
        Self {
            state,
            plugins: Vec::new(),
            plugin_settings: config.plugin_settings,
            search_path: config.search_path,
            initialized: false,
            shut_down: false,
            watcher: None,
            reload_gate: crate::plugins::ReloadGate::default(),
            pending_reloads: Vec::new(),
            last_reload: None,
            retired_images: Vec::new(),
            keep_old_builds: config.keep_old_builds,
            gui: crate::gui::GuiSystem::default(),
            incidents: Vec::new(),
        }
    }

    // ----- plugins -----

    /// Loads a plugin given as a library path or as a NAME looked up in the search path
    /// (see [`PluginSearchPath`]). Returns the plugin's name.
    pub fn load_plugin(&mut self, spec: &str) -> Result<String, PluginLoadError> {
        if looks_like_path(spec) {
            return self.load_plugin_file(Path::new(spec));
        }
        match self.search_path.find(spec) {
            Ok(path) => self.load_plugin_file(&path),
            Err(searched) => Err(self.report(PluginLoadError::NotFound {
                name: spec.to_owned(),
                searched,
            })),
        }
    }

    /// Loads the plugin library at `path` (through a fresh copy). Returns its name.
    pub fn load_plugin_file(&mut self, path: &Path) -> Result<String, PluginLoadError> {
        let opened = open_library(path).map_err(|e| self.report(e))?;
        let library = opened.library;
        let name = library.name().to_owned();
        if self.plugin(&name).is_some() {
            return Err(self.report(PluginLoadError::AlreadyLoaded { plugin: name }));
        }
        let constructed = {
            let _call = PluginCall::enter(CallTag::plugin(&name), Stage::Construct);
            library.instantiate()
        };
        let instance = constructed.map_err(|e| {
            self.report(PluginLoadError::ConstructorFailed {
                plugin: name.clone(),
                message: e.to_string(),
            })
        })?;
        tracing::info!(plugin = %name, version = library.version(), path = %path.display(), "loaded plugin library");
        let origin = PluginOrigin::Library {
            path: path.to_path_buf(),
            loaded_from: opened.loaded_from,
        };
        self.attach(
            name.clone(),
            origin,
            instance,
            Some(library),
            Some(opened.content_hash),
        )?;
        self.watch_new_plugin(path);
        Ok(name)
    }

    /// Adds an in-process plugin value under `name`. It goes through the same ABI adapter
    /// as a loaded library.
    pub fn add_plugin<P: Plugin>(
        &mut self,
        name: &'static str,
        plugin: P,
    ) -> Result<(), PluginLoadError> {
        if self.plugin(name).is_some() {
            return Err(self.report(PluginLoadError::AlreadyLoaded {
                plugin: name.to_owned(),
            }));
        }
        let instance = PluginInstance::from_plugin(name, plugin).map_err(|e| {
            self.report(PluginLoadError::ConstructorFailed {
                plugin: name.to_owned(),
                message: e.to_string(),
            })
        })?;
        self.attach(
            name.to_owned(),
            PluginOrigin::InProcess,
            instance,
            None,
            None,
        )
    }

    fn attach(
        &mut self,
        name: String,
        origin: PluginOrigin,
        instance: PluginInstance,
        library: Option<PluginLibrary>,
        content_hash: Option<u64>,
    ) -> Result<(), PluginLoadError> {
        let settings: Vec<(String, String)> = self
            .plugin_settings
            .iter()
            .filter(|(plugin, _, _)| *plugin == name)
            .map(|(_, k, v)| (k.clone(), v.clone()))
            .collect();
        let mut slot = PluginSlot {
            name: name.clone(),
            tag: crate::watchdog::CallTag::plugin(&name),
            origin,
            instance,
            library,
            status: PluginStatus::Running,
            settings,
            content_hash,
            reloads: 0,
        };
        let info = AttachInfo {
            reload: false,
            settings: slot.settings.clone(),
        };
        let attached = {
            let state = &mut self.state;
            let _call = PluginCall::enter(slot.tag, Stage::Attach);
            let mut cx = crate::services::CallContext::new(state, &name);
            slot.instance.on_attach(&mut cx, &info)
        };
        if let Err(error) = attached {
            return Err(self.report(PluginLoadError::AttachFailed {
                plugin: name,
                message: error.to_string(),
            }));
        }
        self.state
            .io
            .events
            .push(Event::Platform(PlatformEvent::PluginLoaded {
                plugin: name.clone(),
            }));
        if self.initialized {
            slot.call(&mut self.state, Stage::Init, |p, cx| p.on_init(cx));
        }
        self.plugins.push(slot);
        Ok(())
    }

    /// Raises a load error as a platform event; returns it (the caller reports it: the CLI
    /// in one `onyx:` line, the frame's plugin requests in the log).
    fn report(&mut self, error: PluginLoadError) -> PluginLoadError {
        tracing::debug!("{error}");
        self.state
            .io
            .events
            .push(Event::Platform(PlatformEvent::Error {
                message: error.to_string(),
            }));
        error
    }

    /// Detaches and removes the plugin `name`. Returns `false` if there is none.
    pub fn unload_plugin(&mut self, name: &str) -> bool {
        self.unload_retired_images();
        let Some(index) = self.plugins.iter().position(|p| p.name == name) else {
            return false;
        };
        let mut slot = self.plugins.remove(index);
        slot.call(&mut self.state, Stage::Detach, |p, cx| p.on_detach(cx));
        let incident = slot.dispose(&mut self.state);
        // A `Drop` that panicked may have left anything behind: its image stays.
        let dropped_cleanly = incident.is_none();
        self.incidents.extend(incident);
        self.gui.forget(name);
        self.state.tools.scripts.remove_plugin(name);
        if let (Some(watcher), PluginOrigin::Library { path, .. }) =
            (&mut self.watcher, &slot.origin)
        {
            watcher.unwatch(path);
        }
        let origin = slot.origin.clone();
        if let (Some(library), PluginOrigin::Library { loaded_from, .. }, true) =
            (slot.library.take(), &origin, dropped_cleanly)
        {
            drop(slot); // the dropped object lets go of its image
            let fate = crate::plugins::unload_image(library, loaded_from, self.keep_old_builds);
            tracing::debug!(plugin = name, "the unloaded plugin's image: {fate}");
        }
        self.state
            .io
            .events
            .push(Event::Platform(PlatformEvent::PluginUnloaded {
                plugin: name.to_owned(),
            }));
        true
    }

    /// The loaded plugins, in load (= call) order.
    pub fn plugins(&self) -> &[PluginSlot] {
        &self.plugins
    }

    /// The plugin named `name`.
    pub fn plugin(&self, name: &str) -> Option<&PluginSlot> {
        self.plugins.iter().find(|p| p.name == name)
    }

    // ----- the frame -----

    /// Calls `on_init` on every plugin, once. [`Host::frame`] does it on the first frame;
    /// plugins added later are initialised as they attach.
    pub fn init(&mut self) {
        if self.initialized {
            return;
        }
        self.initialized = true;
        for slot in &mut self.plugins {
            slot.call(&mut self.state, Stage::Init, |p, cx| p.on_init(cx));
        }
    }

    /// Queues an event for the next dispatch (input events also update the input state then).
    /// An input event holding a number no device sends is dropped (NaN, infinity) or brought
    /// into range (a scroll of `-f32::MAX`) first.
    pub fn push_event(&mut self, event: impl Into<Event>) {
        let event = match event.into() {
            Event::Input(input) => match crate::gui::input_sanitizer::sanitized(input) {
                Some(input) => Event::Input(input),
                None => {
                    tracing::debug!("an input event with a non-finite value was dropped");
                    return;
                }
            },
            other => other,
        };
        self.state.io.events.push(event);
    }

    /// Runs one frame that took `real_dt` seconds of real time.
    pub fn frame(&mut self, real_dt: f64) -> FrameReport {
        self.init();
        self.begin_tool_frame();
        self.poll_hot_reload();
        self.state.io.debug_lines.clear();
        self.state.io.sent.clear();
        self.dispatch_events();
        let steps = self.state.clock.begin_frame(real_dt);
        for _ in 0..steps {
            // The poses being left behind, with whatever this frame spawned or moved so far.
            self.state.world.propagate();
            crate::render::previous_pose::snapshot(&mut self.state.world);
            for slot in &mut self.plugins {
                slot.call(&mut self.state, Stage::FixedUpdate, |p, cx| {
                    p.on_fixed_update(cx)
                });
            }
            let dt = self.state.clock.fixed_delta() as f32;
            let state = &mut self.state;
            let physics_start = std::time::Instant::now();
            let raised = state.io.events.len();
            // World poses before physics reads them, and after it moved bodies (their
            // children follow).
            state.world.propagate();
            state
                .physics
                .step(&mut state.world, dt, &mut state.io.events);
            state.world.propagate();
            state.tools.diagnostics.physics += physics_start.elapsed();
            crate::console::trace_errors("physics", &state.io.events[raised..]);
            self.state.clock.tick();
        }
        let dt = self.state.clock.time().delta;
        // Animated poses before plugins read them.
        self.state.animation.advance(&mut self.state.world, dt);
        for slot in &mut self.plugins {
            let flow = slot.call(&mut self.state, Stage::Update, |p, cx| p.on_update(cx, dt));
            if flow == Some(Flow::Quit) {
                tracing::info!(plugin = %slot.name, "plugin returned Flow::Quit");
                self.state.io.quit_requested = true;
            }
        }
        self.run_scripts(dt);
        for slot in &mut self.plugins {
            slot.call(&mut self.state, Stage::Render, |p, cx| p.on_render(cx));
        }
        self.draw_gui();
        // World poses of everything the frame's plugins moved, before drawing.
        self.state.world.propagate();
        let input = self.state.io.input;
        self.state.view.orbit.control(&input);
        self.state.io.input.end_frame();
        self.state.clock.end_frame();
        self.apply_plugin_requests();
        // The frame's new builds have run; the images they replaced go now, off the swap.
        self.unload_retired_images();
        self.end_tool_frame(steps);
        FrameReport {
            fixed_steps: steps,
            quit: self.state.io.quit_requested,
        }
    }

    /// The `DrawGui` stage: each plugin that draws a GUI runs its egui frame; plugins that
    /// never override `draw_gui` are asked once and then skipped.
    fn draw_gui(&mut self) {
        if self.gui.all_inactive(self.plugins.len())
            || !self
                .plugins
                .iter_mut()
                .any(|slot| !slot.status.is_faulted() && self.gui.wants_call(&slot.name))
        {
            self.gui.skip_frame();
            return;
        }
        // GUIs live in real time: a paused or slowed scene's tools still respond.
        let (total, delta) = self.state.clock.real_time();
        let input = self.gui.begin_frame(total, delta);
        for slot in &mut self.plugins {
            if slot.status.is_faulted() || !self.gui.wants_call(&slot.name) {
                continue;
            }
            let answer = slot.call(&mut self.state, Stage::DrawGui, |p, cx| {
                p.draw_gui(cx, &input)
            });
            self.gui.accept(&slot.name, answer);
        }
        self.gui.end_frame();
    }

    /// Plugin GUIs: input, outputs, the widgets tests look up.
    pub fn gui(&self) -> &crate::gui::GuiSystem {
        &self.gui
    }

    /// Plugin GUIs, mutably (window size and scale, the window's egui input, AccessKit).
    pub fn gui_mut(&mut self) -> &mut crate::gui::GuiSystem {
        &mut self.gui
    }

    /// The rectangles (points) of the widgets labelled `label` in the topmost plugin UI that
    /// shows any, in tree order (needs `gui_mut().set_accesskit(true)` and a frame since).
    pub fn find_widgets(&self, label: &str) -> Vec<egui::Rect> {
        self.find_widgets_where(|text| text == label)
    }

    /// [`Host::find_widgets`] for the widgets whose label (or value) passes `test`.
    pub fn find_widgets_where(&self, test: impl Fn(&str) -> bool) -> Vec<egui::Rect> {
        let order: Vec<&str> = self.plugins.iter().map(|p| p.name.as_str()).collect();
        self.gui.find_widgets_where(&order, test)
    }

    fn dispatch_events(&mut self) {
        let mut events = std::mem::take(&mut self.state.io.events);
        // Input a plugin's UI takes (a click on its window, typing into its text field)
        // goes to the UI only.
        events.retain(|event| match event {
            Event::Input(input) => self.gui.route(input),
            Event::Window(WindowEvent::Resized { width, height }) => {
                self.gui.input_mut().set_screen_size(*width, *height);
                true
            }
            Event::Window(WindowEvent::Focused(focused)) => {
                self.gui.input_mut().set_focused(*focused);
                true
            }
            _ => true,
        });
        for event in &events {
            match event {
                Event::Input(input) => self.state.io.input.apply(input),
                Event::Window(WindowEvent::Focused(false)) => self.state.io.input.release_all(),
                _ => {}
            }
        }
        for event in &events {
            let closing = matches!(event, Event::Window(WindowEvent::CloseRequested));
            if closing {
                self.state.io.close_requested = true;
                self.state.io.close_kept_by = None;
            }
            for slot in &mut self.plugins {
                slot.call(&mut self.state, Stage::Event, |p, cx| p.on_event(cx, event));
            }
            self.state.io.close_requested = false;
            match event {
                Event::Window(WindowEvent::Resized { width, height }) => {
                    let (w, h) = (*width, *height);
                    for slot in &mut self.plugins {
                        slot.call(&mut self.state, Stage::Resize, |p, cx| {
                            p.on_resize(cx, w, h)
                        });
                    }
                }
                // A plugin with unsaved work may keep the window open to ask first.
                Event::Window(WindowEvent::CloseRequested)
                    if self.state.io.close_kept_by.is_none() =>
                {
                    self.state.io.quit_requested = true;
                }
                _ => {}
            }
        }
    }

    /// Whether a plugin or the window asked to quit.
    pub fn quit_requested(&self) -> bool {
        self.state.io.quit_requested
    }

    /// Calls `on_detach` on every running plugin, in reverse load order, once.
    pub fn shutdown(&mut self) {
        if self.shut_down {
            return;
        }
        self.shut_down = true;
        self.unload_retired_images();
        for slot in self.plugins.iter_mut().rev() {
            slot.call(&mut self.state, Stage::Detach, |p, cx| p.on_detach(cx));
        }
        // Dropped in the same order, each inside its own image; a panicking `Drop` faults
        // its plugin (the status says so) and the others are still dropped.
        for slot in self.plugins.iter_mut().rev() {
            slot.dispose(&mut self.state);
        }
    }

    /// Everything that made this run unclean apart from the status of the plugins still
    /// loaded: a plugin that panicked while being dropped after an unload or a reload, a
    /// reload whose state could not be carried over. One sentence each.
    pub fn incidents(&self) -> &[String] {
        &self.incidents
    }

    // ----- world, time, scenes -----

    /// The world.
    pub fn world(&self) -> &hecs::World {
        &self.state.world.ecs
    }

    /// The world, mutably (host-side tools; plugins go through `Ctx`). The scene graph is
    /// rebuilt from it before the next world poses are read.
    pub fn world_mut(&mut self) -> &mut hecs::World {
        self.state.world.hierarchy.invalidate();
        &mut self.state.world.ecs
    }

    /// The world pose of `entity` (its transform with every ancestor's applied), exact
    /// after every write so far; `None` for an entity that does not exist.
    pub fn world_pose(
        &self,
        entity: onyx_plugin_api::Entity,
    ) -> Option<onyx_plugin_api::GlobalTransform> {
        let e = self.state.world.entity(entity)?;
        Some(onyx_plugin_api::GlobalTransform(
            self.state.world.world_pose(e),
        ))
    }

    /// Every visible mesh and the world pose the renderer draws it at this frame (its world
    /// pose interpolated between the last two fixed steps): what a screenshot would show,
    /// without a GPU.
    pub fn drawn_poses(&self) -> Vec<(onyx_plugin_api::Entity, onyx_plugin_api::GlobalTransform)> {
        let mut poses = Vec::new();
        let alpha = self.state.clock.time().alpha;
        crate::render::drawn_poses(&self.state.world, alpha, |e, pose, _| {
            poses.push((
                crate::entity_id::to_api(e),
                onyx_plugin_api::GlobalTransform(pose),
            ));
        });
        poses.sort_by_key(|(e, _)| *e);
        poses
    }

    /// The children of `entity`, in the order they were attached (empty for an entity that
    /// does not exist).
    pub fn children(&mut self, entity: onyx_plugin_api::Entity) -> Vec<onyx_plugin_api::Entity> {
        match self.state.world.entity(entity) {
            Some(e) => self
                .state
                .world
                .children(e)
                .into_iter()
                .map(crate::entity_id::to_api)
                .collect(),
            None => Vec::new(),
        }
    }

    /// Runs `f` with the services a call of plugin `plugin` is served by: what a plugin's
    /// `Ctx` reaches, without a plugin (benchmarks measure the boundary with it).
    pub fn with_services<R>(
        &mut self,
        plugin: &str,
        f: impl FnOnce(&mut dyn onyx_plugin_api::host::HostServices) -> R,
    ) -> R {
        let mut cx = crate::services::CallContext::new(&mut self.state, plugin);
        f(&mut cx)
    }

    /// The clock as plugins see it.
    pub fn time(&self) -> Time {
        self.state.clock.time()
    }

    /// Length of one fixed step, seconds.
    pub(crate) fn clock_ref_fixed_delta(&self) -> f64 {
        self.state.clock.fixed_delta()
    }

    /// The clock.
    pub fn clock_mut(&mut self) -> &mut FixedClock {
        &mut self.state.clock
    }

    /// Spawns the entities of the scene file at `path` (added to what is there). On error
    /// the world is unchanged and the error is also raised as a platform event.
    /// A scene that sets `physics` also sets the fixed step rate and the physics settings.
    /// The file becomes the world's scene file (`Ctx::scene_path`: the one tools save to),
    /// unless it is a glTF file (saving would overwrite the model).
    ///
    /// A glTF file is imported with the settings given for it
    /// ([`Host::set_import_settings`], or an `imports` entry of a scene loaded before).
    pub fn load_scene(&mut self, path: &Path) -> Result<usize, SceneError> {
        let settings = self.state.world.assets.file_import_settings(path);
        let loaded = scene::read_scene_with(path, &settings).and_then(|file| {
            let world = &mut self.state.world;
            let n = scene::spawn_scene(&mut world.ecs, &mut world.assets, &file, path)?;
            world.hierarchy.invalidate();
            if let Some(physics) = file.physics {
                self.set_physics(physics);
            }
            Ok(n)
        });
        match &loaded {
            Ok(n) => {
                tracing::info!(path = %path.display(), entities = n, "loaded scene");
                // A glTF file opened as a scene is not where the scene is saved to.
                self.state.tools.scene_path =
                    (!scene::is_gltf_scene(path)).then(|| path.to_path_buf());
            }
            Err(error) => {
                // Returned to the caller, who reports it; plugins hear of it as an event.
                tracing::debug!("{error}");
                self.push_event(PlatformEvent::Error {
                    message: error.to_string(),
                });
            }
        }
        loaded
    }

    /// Brings the model file at `path` in with `settings` from now on, as a scene's
    /// `imports` entry for it would: a glTF file loaded as a scene after this is scaled and
    /// turned as one piece at its root (`onyx run --scene model.glb --import-scale ..`).
    pub fn set_import_settings(&mut self, path: &Path, settings: onyx_render::ImportSettings) {
        self.state.world.assets.set_import_settings(path, settings);
    }

    /// The file tools save the scene to: the last scene file loaded or saved (never a glTF
    /// file opened as a scene).
    pub fn scene_path(&self) -> Option<&Path> {
        self.state.tools.scene_path.as_deref()
    }

    /// Saves the world to `path` atomically.
    /// The physics settings chosen by a scene or [`Host::set_physics`] are saved with it.
    pub fn save_scene(&self, path: &Path) -> Result<(), SceneError> {
        let mut file = scene::scene_from_world(&self.state.world);
        file.physics = self.state.physics.scene_physics().cloned();
        scene::write_scene(&file, path)
    }

    /// Simulates with a preset and overrides from now on: sets the fixed step rate (the
    /// physics step rate) and the physics settings. Saved with the scene.
    pub fn set_physics(&mut self, physics: crate::physics::ScenePhysics) {
        if !self.state.clock.set_fixed_hz(physics.fixed_hz()) {
            tracing::warn!(fixed_hz = physics.fixed_hz(), "invalid fixed rate ignored");
        }
        tracing::info!(
            preset = %physics.preset,
            fixed_hz = physics.fixed_hz(),
            substeps = physics.settings().substeps,
            "physics settings"
        );
        self.state.physics.set_scene_physics(physics);
    }

    /// Draws the world into `target` with `system` (after [`Host::frame`]).
    pub fn render(
        &mut self,
        system: &mut crate::render::RenderSystem,
        target: &mut impl onyx_render::RenderTarget,
    ) -> Result<onyx_render::RenderStats, onyx_render::RenderError> {
        let raised = self.state.io.events.len();
        let (input, events) = self.state.render_input();
        let stats = crate::render::render_with_gui(system, input, events, target, &self.gui);
        crate::console::trace_errors("render", &self.state.io.events[raised..]);
        let stats = stats?;
        self.record_render_stats(&stats);
        Ok(stats)
    }

    /// Draws the world into a `width` × `height` image with `system`. Unlike a frame, it
    /// waits for the models and textures it draws to finish loading (at most
    /// [`SCREENSHOT_LOAD_TIMEOUT`]; a warning names what was still loading), so a
    /// screenshot shows the final assets, not placeholders.
    pub fn render_image(
        &mut self,
        system: &mut crate::render::RenderSystem,
        width: u32,
        height: u32,
    ) -> Result<onyx_render::image::RgbaImage, crate::render::ScreenshotError> {
        let max = system
            .renderer()
            .gpu()
            .device()
            .limits()
            .max_texture_dimension_2d;
        if width > max || height > max {
            return Err(crate::render::ScreenshotError::TooLarge { width, height, max });
        }
        let raised = self.state.io.events.len();
        system.await_loads = Some(SCREENSHOT_LOAD_TIMEOUT);
        let image = {
            let (input, events) = self.state.render_input();
            crate::render::render_image_with_gui(system, input, events, width, height, &self.gui)
        };
        system.await_loads = None;
        crate::console::trace_errors("render", &self.state.io.events[raised..]);
        let image = image?;
        self.record_render_stats(&system.renderer().stats());
        Ok(image)
    }

    /// The physics system (its settings, world and debug lines).
    pub fn physics(&self) -> &crate::physics::PhysicsSystem {
        &self.state.physics
    }

    /// The physics system, mutably (to tune its settings).
    pub fn physics_mut(&mut self) -> &mut crate::physics::PhysicsSystem {
        &mut self.state.physics
    }

    /// The mesh and texture ids handed out so far.
    pub fn assets(&self) -> &crate::assets::AssetRegistry {
        &self.state.world.assets
    }

    /// Registers a model file (as `Ctx::load_mesh` does) and returns its id.
    pub fn load_mesh(&mut self, path: &Path) -> onyx_plugin_api::MeshId {
        self.state.world.assets.mesh(path)
    }

    /// Registers an image file (as `Ctx::load_texture` does) and returns its id.
    pub fn load_texture(&mut self, path: &Path) -> onyx_plugin_api::TextureId {
        self.state.world.assets.texture(path)
    }

    /// The state as JSON: what `onyx run --dump-state` writes (format in the README).
    pub fn dump_state(&self) -> serde_json::Value {
        dump_state(&self.state, &self.plugins)
    }
}

impl Drop for Host {
    fn drop(&mut self) {
        self.shutdown();
    }
}
