//! Conversions between the plugin API's [`Entity`] and hecs's.

use onyx_plugin_api::Entity;

/// The API handle of a hecs entity.
pub fn to_api(entity: hecs::Entity) -> Entity {
    Entity::from_bits(entity.to_bits().get())
}

/// The hecs entity of an API handle, if the bits can name one.
pub fn to_hecs(entity: Entity) -> Option<hecs::Entity> {
    hecs::Entity::from_bits(entity.to_bits())
}
