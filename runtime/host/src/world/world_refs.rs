//! [`WorldRefs`]: what a component's checks and file form may ask about the world — assets by
//! id and path, entities and the ids a file or dump names them by.

use std::collections::HashMap;

use onyx_plugin_api::{AnimationId, Entity, HostRefs, MeshId, TextureId};

use crate::assets::AssetRegistry;
use crate::entity_id::to_hecs;

/// [`HostRefs`] over a world and its assets. Entities are named by `file_ids` when given (a
/// scene being saved), else by their handle's bits (a state dump, whose `id`s they are).
pub struct WorldRefs<'a> {
    pub(crate) ecs: &'a hecs::World,
    pub(crate) assets: &'a AssetRegistry,
    pub(crate) file_ids: Option<&'a HashMap<hecs::Entity, u64>>,
}

impl HostRefs for WorldRefs<'_> {
    fn knows_mesh(&self, mesh: MeshId) -> bool {
        self.assets.knows_mesh(mesh)
    }

    fn knows_texture(&self, texture: TextureId) -> bool {
        self.assets.knows_texture(texture)
    }

    fn mesh_file(&self, mesh: MeshId) -> Option<String> {
        self.assets.mesh_path(mesh).map(|p| p.display().to_string())
    }

    fn texture_file(&self, texture: TextureId) -> Option<String> {
        self.assets
            .texture_path(texture)
            .map(|p| p.display().to_string())
    }

    fn knows_animation(&self, animation: AnimationId) -> bool {
        self.assets.knows_animation(animation)
    }

    fn animation_file(&self, animation: AnimationId) -> Option<String> {
        self.assets
            .animation_path(animation)
            .map(|p| p.display().to_string())
    }

    fn contains(&self, entity: Entity) -> bool {
        to_hecs(entity).is_some_and(|e| self.ecs.contains(e))
    }

    fn file_id(&self, entity: Entity) -> Option<u64> {
        match self.file_ids {
            Some(ids) => ids.get(&to_hecs(entity)?).copied(),
            None => Some(entity.to_bits()),
        }
    }
}
