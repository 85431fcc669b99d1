//! Scripts: the [`Script`] component names a behaviour a plugin registered; the host calls
//! that plugin's [`Plugin::on_script`](crate::Plugin::on_script) for each entity holding it.

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use crate::{Component, CtxError, Entity};

/// Runs the behaviour `name` (registered with [`Ctx::register_script`](crate::Ctx::register_script))
/// on this entity, with `params` (any JSON value; the behaviour's own settings). Saved in
/// scene files like any component.
///
/// ```no_run
/// # use onyx_plugin_api::*;
/// # fn demo(ctx: &mut Ctx) -> Result<(), CtxError> {
/// ctx.spawn((Name::new("fan"), Transform::IDENTITY, Script::new("Rotator").with_params(&serde_json::json!({"speed": 2.0}))?))?;
/// # Ok(()) }
/// ```
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Script {
    /// The behaviour's registered name.
    pub name: String,
    /// Its parameters.
    #[serde(default)]
    pub params: serde_json::Value,
}

impl Component for Script {
    const NAME: &'static str = "onyx.Script";
}

impl Script {
    /// The behaviour `name` with no parameters.
    pub fn new(name: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            params: serde_json::Value::Null,
        }
    }

    /// Sets the parameters from any serde value.
    pub fn with_params(mut self, params: &impl Serialize) -> Result<Self, CtxError> {
        self.params = serde_json::to_value(params).map_err(|e| CtxError::Encode {
            component: Self::NAME.to_owned(),
            message: e.to_string(),
        })?;
        Ok(self)
    }
}

/// When the host calls a script.
#[repr(u8)]
#[derive(
    abi_stable::StableAbi, Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize,
)]
pub enum ScriptPhase {
    /// The entity got the script (or play started); called once before the first update.
    Created,
    /// Once per frame while playing, after `on_update`.
    Update,
    /// The script, its entity, or the play session ended.
    Destroyed,
}

/// One call of a script, as [`Plugin::on_script`](crate::Plugin::on_script) receives it.
#[derive(Clone, Debug, PartialEq)]
pub struct ScriptCall {
    /// The entity running it.
    pub entity: Entity,
    /// Which call this is.
    pub phase: ScriptPhase,
    /// The behaviour's name.
    pub name: String,
    /// The entity's parameters for it (`Null` when none).
    pub params: serde_json::Value,
    /// Scaled frame time, seconds (0 outside `Update`).
    pub dt: f32,
}

impl ScriptCall {
    /// The parameters as `T`; missing parameters (`null`) give `T::default()`.
    pub fn params_as<T: DeserializeOwned + Default>(&self) -> Result<T, CtxError> {
        if self.params.is_null() {
            return Ok(T::default());
        }
        T::deserialize(&self.params).map_err(|e| CtxError::Decode {
            component: format!("parameters of script `{}`", self.name),
            message: e.to_string(),
        })
    }
}

/// A registered script, as [`Ctx::registered_scripts`](crate::Ctx::registered_scripts) lists it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ScriptInfo {
    /// Its name.
    pub name: String,
    /// The plugin that runs it.
    pub plugin: String,
    /// The parameters a new [`Script`] of this kind starts with.
    pub default_params: serde_json::Value,
}
