//! [`PhysicsSystem::reset`]: forget every body, keeping the settings (the world was replaced).

use super::PhysicsSystem;

impl PhysicsSystem {
    /// Drops every body, contact and pending command, keeping the settings (and the scene's
    /// physics preset). Used when the whole world is replaced — a new or opened scene, or the
    /// editor's Stop — so bodies are rebuilt from the components on the next step.
    pub fn reset(&mut self) {
        let settings = *self.world().settings();
        let scene = self.scene_physics().cloned();
        *self = PhysicsSystem::new(settings);
        if let Some(scene) = scene {
            self.set_scene_physics(scene);
        }
        *self.settings_mut() = settings;
    }
}
