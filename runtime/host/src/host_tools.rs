//! The tool services' part of the frame: plugin list and diagnostics refreshed, scripts run,
//! the world put back after a Stop. `Host::frame` calls these at fixed points.

use onyx_plugin_api::host::PlayCommand;
use onyx_plugin_api::tools::{Diagnostics, PluginInfo, PluginState};
use onyx_plugin_api::PlayMode;

use crate::plugins::{PluginOrigin, PluginStatus};
use crate::Host;

impl Host {
    /// Start of a frame: timings reset, the plugin list refreshed for plugin calls.
    pub(crate) fn begin_tool_frame(&mut self) {
        self.state.tools.diagnostics.begin_frame();
        self.refresh_plugin_infos();
    }

    fn refresh_plugin_infos(&mut self) {
        // Rebuilt only when a plugin came, went, reloaded or faulted (no allocation per
        // frame otherwise).
        let signature = self
            .plugins
            .iter()
            .fold(self.plugins.len() as u64, |acc, slot| {
                acc.wrapping_mul(31)
                    .wrapping_add(slot.reloads() as u64 * 2 + u64::from(slot.status().is_faulted()))
                    .wrapping_add(slot.name().len() as u64)
            });
        if self.state.tools.plugin_infos_signature == Some(signature) {
            return;
        }
        self.state.tools.plugin_infos_signature = Some(signature);
        self.state.tools.plugin_infos = self
            .plugins
            .iter()
            .map(|slot| PluginInfo {
                name: slot.name().to_owned(),
                state: match slot.status() {
                    PluginStatus::Running => PluginState::Running,
                    PluginStatus::Faulted { stage, message } => PluginState::Faulted {
                        stage: stage.as_str().to_owned(),
                        message: message.clone(),
                    },
                },
                path: match slot.origin() {
                    PluginOrigin::Library { path, .. } => Some(path.display().to_string()),
                    PluginOrigin::InProcess => None,
                },
                reloads: slot.reloads(),
            })
            .collect();
    }

    /// After `on_update`: this frame's scripts.
    pub(crate) fn run_scripts(&mut self, dt: f32) {
        crate::host_scripts::run_scripts(&mut self.plugins, &mut self.state, dt);
    }

    /// End of a frame: a Stop puts the world back (after the scripts were told), and the
    /// frame's figures become [`Host::diagnostics`].
    pub(crate) fn end_tool_frame(&mut self, fixed_steps: u32) {
        if let Some(snapshot) = self.state.tools.play.take_restore() {
            self.run_scripts(0.0);
            snapshot.restore(&mut self.state.world.ecs);
            self.state.world.hierarchy.invalidate();
            self.state.physics.reset();
            self.state.tools.world_generation += 1;
            tracing::info!(
                entities = snapshot.len(),
                "world restored to its state at Play"
            );
        }
        let tools = &mut self.state.tools;
        let (frame_ms, frame_interval_ms) = tools.diagnostics.frame_times_ms();
        let physics = self.state.physics.world();
        let counters = physics.last_step().counters;
        let dynamic = physics
            .bodies()
            .iter()
            .filter(|(_, b)| b.body_type().is_dynamic())
            .count() as u32;
        let previous = std::mem::take(&mut tools.diagnostics.last);
        tools.diagnostics.last = Diagnostics {
            frame_ms,
            frame_interval_ms,
            fixed_steps,
            physics_ms: tools.diagnostics.physics.as_secs_f64() * 1000.0,
            contacts: counters.contacts,
            awake_bodies: counters.awake_bodies,
            asleep_bodies: dynamic.saturating_sub(counters.awake_bodies),
            draw_calls: previous.draw_calls,
            triangles: previous.triangles,
            instances: previous.instances,
            entities: self.state.world.ecs.len(),
            // Filled in when read (see `Host::diagnostics`): building it every frame cost
            // every plugin a few hundred nanoseconds.
            plugins: Vec::new(),
        };
        tools.diagnostics.timer.end_frame();
    }

    /// Keeps the figures of the image just drawn for the diagnostics.
    pub(crate) fn record_render_stats(&mut self, stats: &onyx_render::RenderStats) {
        if stats.skipped {
            return;
        }
        let last = &mut self.state.tools.diagnostics.last;
        last.draw_calls = stats.draw_calls;
        last.triangles = stats.triangles;
        last.instances = stats.instances;
    }

    /// Figures of the last complete frame (what `Ctx::diagnostics` returns).
    pub fn diagnostics(&self) -> Diagnostics {
        self.state.tools.diagnostics()
    }

    /// Edit, Playing or Paused.
    pub fn play_mode(&self) -> PlayMode {
        self.state.tools.play.mode()
    }

    /// Plays, pauses, steps or stops, as `Ctx::play` and friends do.
    pub fn play_command(&mut self, command: PlayCommand) {
        let state = &mut self.state;
        state
            .tools
            .play
            .command(command, &state.world.ecs, &mut state.clock);
    }
}
