//! [`Component`]: a plugin's own per-entity data, stored by name in the host's world.

use serde::{de::DeserializeOwned, Serialize};

/// A plugin-defined component: any serde type with a stable, unique name.
///
/// The host stores it serialized under [`Component::NAME`], so it survives scene save and
/// load, hot reload, and is shown decoded in `--dump-state`. Type identity is the name, never
/// a `TypeId` (those change with every build). Prefix names with your plugin's name.
///
/// ```
/// use onyx_plugin_api::Component;
/// use serde::{Deserialize, Serialize};
///
/// #[derive(Serialize, Deserialize)]
/// struct Health { hp: u32 }
///
/// impl Component for Health {
///     const NAME: &'static str = "my_game.health";
/// }
/// ```
pub trait Component: Serialize + DeserializeOwned + 'static {
    /// The stable name the component is stored under.
    const NAME: &'static str;
}
