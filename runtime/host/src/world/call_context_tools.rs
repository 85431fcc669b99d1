//! The tool services (`ToolServices`) of [`CallContext`]: world introspection, scenes,
//! plugins, diagnostics, console, play mode, scripts, viewport.

use std::path::Path;

use onyx_plugin_api::glam::Vec2;
use onyx_plugin_api::host::{PlayCommand, ToolServices};
use onyx_plugin_api::tools::{
    ComponentEntry, Diagnostics, EntityList, LogLine, PlayMode, PluginInfo, PluginState, Ray,
    RenderOverrides, ScriptInfo,
};
use onyx_plugin_api::{CtxError, Entity, Name, PlatformEvent};

use super::entity_id::to_api;
use super::{CallContext, HostState};
use crate::scene;

fn scene_error(error: crate::scene::SceneError) -> CtxError {
    CtxError::Invalid {
        message: error.to_string(),
    }
}

impl HostState {
    /// Replaces the whole world (new or opened scene): physics rebuilt from the new
    /// components, the chosen camera forgotten, Stop no longer restores an older world.
    pub fn replace_world(&mut self, world: hecs::World) {
        self.world = world;
        self.after_world_replaced();
        self.tools.play.forget_snapshot();
    }

    /// Bookkeeping after the world's entities were all replaced.
    pub fn after_world_replaced(&mut self) {
        self.physics.reset();
        self.camera_override = None;
        self.tools.world_generation += 1;
    }
}

impl ToolServices for CallContext<'_> {
    fn entity_list(&mut self) -> EntityList {
        let world = &self.state.world;
        let mut rows: Vec<(hecs::Entity, Option<hecs::Ref<'_, Name>>)> = world
            .iter()
            .map(|e| (e.entity(), e.get::<&Name>()))
            .collect();
        rows.sort_by_key(|(e, _)| e.to_bits());
        let mut list = EntityList::default();
        for (e, name) in &rows {
            list.push(to_api(*e), name.as_deref().map_or("", Name::as_str));
        }
        list
    }

    fn components_of(&mut self, entity: Entity) -> Result<Vec<ComponentEntry>, CtxError> {
        self.list_components(entity)
    }

    fn set_component_json(
        &mut self,
        entity: Entity,
        type_name: &str,
        json: &str,
    ) -> Result<(), CtxError> {
        self.write_component_json(entity, type_name, json)
    }

    fn add_component(&mut self, entity: Entity, type_name: &str) -> Result<(), CtxError> {
        self.add_default_component(entity, type_name)
    }

    fn remove_component(&mut self, entity: Entity, type_name: &str) -> Result<(), CtxError> {
        self.remove_component_named(entity, type_name)
    }

    fn new_scene(&mut self) -> Result<(), CtxError> {
        tracing::info!(plugin = self.plugin, "new scene");
        self.state.replace_world(hecs::World::new());
        self.state.tools.scene_path = None;
        Ok(())
    }

    fn open_scene(&mut self, path: &str) -> Result<(), CtxError> {
        let path = Path::new(path);
        let mut world = hecs::World::new();
        let opened = scene::read_scene(path).and_then(|file| {
            let count = scene::spawn_scene(&mut world, &mut self.state.assets, &file, path)?;
            Ok((count, file.physics))
        });
        match opened {
            Ok((count, physics)) => {
                tracing::info!(path = %path.display(), entities = count, "opened scene");
                self.state.replace_world(world);
                if let Some(physics) = physics {
                    self.state.clock.set_fixed_hz(physics.fixed_hz());
                    self.state.physics.set_scene_physics(physics);
                }
                self.state.tools.scene_path = Some(path.to_path_buf());
                Ok(())
            }
            Err(error) => {
                tracing::error!("{error}");
                self.state.pending_events.push(
                    PlatformEvent::Error {
                        message: error.to_string(),
                    }
                    .into(),
                );
                Err(scene_error(error))
            }
        }
    }

    fn save_scene(&mut self, path: &str) -> Result<(), CtxError> {
        let path = Path::new(path);
        let mut file = scene::scene_from_world(&self.state.world, &self.state.assets);
        file.physics = self.state.physics.scene_physics().cloned();
        scene::write_scene(&file, path).map_err(scene_error)?;
        tracing::info!(path = %path.display(), "saved scene");
        self.state.tools.scene_path = Some(path.to_path_buf());
        Ok(())
    }

    fn scene_path(&mut self) -> Option<String> {
        let path = self.state.tools.scene_path.as_ref()?;
        Some(path.display().to_string())
    }

    fn plugin_infos(&mut self) -> Vec<PluginInfo> {
        self.state.tools.plugin_infos.clone()
    }

    fn diagnostics(&mut self) -> Diagnostics {
        self.state.tools.diagnostics()
    }

    fn log_lines_since(&mut self, seq: u64) -> Vec<LogLine> {
        crate::console::console_log().since(seq)
    }

    fn play_command(&mut self, command: PlayCommand) {
        let state = &mut *self.state;
        state
            .tools
            .play
            .command(command, &state.world, &mut state.clock);
    }

    fn play_mode(&self) -> PlayMode {
        self.state.tools.play.mode()
    }

    fn register_script(
        &mut self,
        name: &str,
        default_params: serde_json::Value,
    ) -> Result<(), CtxError> {
        let infos = &self.state.tools.plugin_infos;
        let loaded = |owner: &str| {
            infos
                .iter()
                .any(|p| p.name == owner && p.state == PluginState::Running)
        };
        self.state
            .tools
            .scripts
            .register(self.plugin, name, default_params, loaded)?;
        tracing::debug!(plugin = self.plugin, script = name, "script registered");
        Ok(())
    }

    fn registered_scripts(&mut self) -> Vec<ScriptInfo> {
        self.state.tools.scripts.all().to_vec()
    }

    fn screen_ray(&mut self, point: Vec2, size: Vec2) -> Option<Ray> {
        crate::render::screen_ray(self.state, point, size)
    }

    fn set_render_overrides(&mut self, overrides: RenderOverrides) {
        self.state.tools.render_overrides = overrides;
    }

    fn render_overrides(&self) -> RenderOverrides {
        self.state.tools.render_overrides
    }
}
