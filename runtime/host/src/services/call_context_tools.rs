//! The tool services (`ToolServices`) of [`CallContext`]: world introspection, scenes,
//! plugins, diagnostics, console, play mode, scripts, viewport.

use std::path::{Path, PathBuf};

use onyx_plugin_api::glam::Vec2;
use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::host::{Blob, PlayCommand, ToolServices};
use onyx_plugin_api::tools::{
    Bounds, Diagnostics, EntityList, LogLine, PlayMode, PluginInfo, PluginState, Ray,
    RenderOverrides, ScriptInfo,
};
use onyx_plugin_api::{BuiltinValue, CtxError, Entity, Name, PlatformEvent, RayHit};

use super::CallContext;
use crate::entity_id::to_api;
use crate::scene::{self, SceneError};

/// A scene error as plugins get it: the sentence, and the file, line and column it names.
fn scene_error(error: SceneError) -> CtxError {
    let (line, column) = match &error {
        SceneError::Parse { line, column, .. } => {
            (u32::try_from(*line).ok(), u32::try_from(*column).ok())
        }
        _ => (None, None),
    };
    CtxError::Scene {
        path: error
            .path()
            .map(|p| p.display().to_string())
            .unwrap_or_default(),
        line,
        column,
        message: error.to_string(),
    }
}

impl ToolServices for CallContext<'_> {
    fn entity_list(&mut self) -> EntityList {
        let world = &mut self.state.world;
        world.hierarchy.refresh_index(&world.ecs);
        let ecs = &world.ecs;
        let mut rows: Vec<(hecs::Entity, Option<hecs::Ref<'_, Name>>)> =
            ecs.iter().map(|e| (e.entity(), e.get::<&Name>())).collect();
        rows.sort_by_key(|(e, _)| e.to_bits());
        let mut list = EntityList::default();
        for (e, name) in &rows {
            list.push(to_api(*e), name.as_deref().map_or("", Name::as_str));
        }
        for (row, (e, _)) in rows.iter().enumerate() {
            if let Some(parent) = world.hierarchy.parent(*e) {
                if let Ok(parent_row) =
                    rows.binary_search_by_key(&parent.to_bits(), |(p, _)| p.to_bits())
                {
                    list.set_parent(row, parent_row);
                }
            }
        }
        list
    }

    fn components_of(
        &mut self,
        entity: Entity,
    ) -> Result<(Vec<BuiltinValue>, Vec<Blob>), CtxError> {
        self.components(entity)
    }

    fn new_scene(&mut self) -> Result<(), CtxError> {
        tracing::info!(plugin = self.plugin, "new scene");
        let old = self.state.world.all_entities();
        self.state.retire_entities(&old);
        self.state.tools.scene_path = None;
        Ok(())
    }

    fn open_scene(&mut self, path: &str) -> Result<(), CtxError> {
        let path = Path::new(path);
        // The scene spawns beside the old entities (and takes itself back on error), then
        // the old ones go: handles are never reused, so one kept from before names nothing.
        let old = self.state.world.all_entities();
        let world = &mut self.state.world;
        let settings = world.assets.file_import_settings(path);
        let opened = scene::read_scene_with(path, &settings).and_then(|file| {
            let count = scene::spawn_scene(&mut world.ecs, &mut world.assets, &file, path)?;
            Ok((count, file.physics))
        });
        match opened {
            Ok((count, physics)) => {
                tracing::info!(path = %path.display(), entities = count, "opened scene");
                self.state.retire_entities(&old);
                if let Some(physics) = physics {
                    self.state.clock.set_fixed_hz(physics.fixed_hz());
                    self.state.physics.set_scene_physics(physics);
                }
                // A glTF file opened as a scene is not where the scene is saved to.
                self.state.tools.scene_path =
                    (!scene::is_gltf_scene(path)).then(|| path.to_path_buf());
                Ok(())
            }
            Err(error) => {
                tracing::error!("{error}");
                self.state.io.events.push(
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
        self.save_scene_copy(path)?;
        tracing::info!(path, "saved scene");
        self.state.tools.scene_path = Some(PathBuf::from(path));
        Ok(())
    }

    fn save_scene_copy(&mut self, path: &str) -> Result<(), CtxError> {
        let mut file = scene::scene_from_world(&self.state.world);
        file.physics = self.state.physics.scene_physics().cloned();
        scene::write_scene(&file, Path::new(path)).map_err(scene_error)
    }

    fn set_scene_path(&mut self, path: Option<&str>) -> Result<(), CtxError> {
        self.state.tools.scene_path = path.map(PathBuf::from);
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
            .command(command, &state.world.ecs, &mut state.clock);
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
        crate::render::screen_ray(&self.state.world, &self.state.view, point, size)
    }

    fn set_render_overrides(&mut self, overrides: RenderOverrides) {
        self.state.view.overrides = overrides;
    }

    fn render_overrides(&self) -> RenderOverrides {
        self.state.view.overrides
    }

    fn pick(&mut self, origin: Vec3, direction: Vec3, max_distance: f32) -> Option<RayHit> {
        let state = &mut *self.state;
        crate::tools::pick(
            &state.world,
            &mut state.tools.mesh_bounds,
            origin,
            direction,
            max_distance,
        )
    }

    fn local_bounds(&mut self, entity: Entity) -> Option<Bounds> {
        let state = &mut *self.state;
        let e = state.world.entity(entity)?;
        crate::tools::local_bounds(&state.world, &mut state.tools.mesh_bounds, e)
    }

    fn import_gltf(&mut self, path: &str) -> Result<Entity, CtxError> {
        let path = Path::new(path);
        let world = &mut self.state.world;
        // The open scene's `imports` entry for the file (if any) says how it comes in.
        let settings = world.assets.file_import_settings(path);
        let spawned = scene::import_gltf_scene(path, false, &settings)
            .map_err(SceneError::from)
            .and_then(|imported| {
                for warning in &imported.warnings {
                    tracing::warn!("`{}`: {warning}", path.display());
                }
                scene::spawn_scene_entities(
                    &mut world.ecs,
                    &mut world.assets,
                    &imported.scene,
                    path,
                )
            });
        match spawned {
            Ok(spawned) => {
                world.hierarchy.invalidate();
                tracing::info!(path = %path.display(), entities = spawned.len(), plugin = self.plugin, "imported glTF");
                spawned
                    .first()
                    .map(|root| to_api(*root))
                    .ok_or_else(|| CtxError::Invalid {
                        message: format!("`{}` gave no entity to import", path.display()),
                    })
            }
            Err(error) => {
                tracing::error!("{error}");
                Err(scene_error(error))
            }
        }
    }
}
