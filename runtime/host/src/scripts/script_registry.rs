//! [`ScriptRegistry`]: the scripts plugins registered.

use onyx_plugin_api::tools::ScriptInfo;
use onyx_plugin_api::CtxError;

/// Registered scripts, by name (names are unique across plugins).
#[derive(Clone, Debug, Default)]
pub struct ScriptRegistry {
    scripts: Vec<ScriptInfo>,
}

impl ScriptRegistry {
    /// Registers `name` for `plugin`. The same plugin may register a name again (after a
    /// hot reload); another plugin's name is refused while `is_loaded(owner)` holds.
    pub fn register(
        &mut self,
        plugin: &str,
        name: &str,
        default_params: serde_json::Value,
        is_loaded: impl Fn(&str) -> bool,
    ) -> Result<(), CtxError> {
        if name.trim().is_empty() {
            return Err(CtxError::Invalid {
                message: "a script needs a non-empty name".into(),
            });
        }
        if let Some(existing) = self.scripts.iter_mut().find(|s| s.name == name) {
            if existing.plugin != plugin && is_loaded(&existing.plugin) {
                return Err(CtxError::Invalid {
                    message: format!(
                        "script `{name}` is already registered by plugin `{}`; pick another name",
                        existing.plugin
                    ),
                });
            }
            existing.plugin = plugin.to_owned();
            existing.default_params = default_params;
            return Ok(());
        }
        self.scripts.push(ScriptInfo {
            name: name.to_owned(),
            plugin: plugin.to_owned(),
            default_params,
        });
        Ok(())
    }

    /// Forgets every script of `plugin` (it was unloaded).
    pub fn remove_plugin(&mut self, plugin: &str) {
        self.scripts.retain(|s| s.plugin != plugin);
    }

    /// The script named `name`.
    pub fn get(&self, name: &str) -> Option<&ScriptInfo> {
        self.scripts.iter().find(|s| s.name == name)
    }

    /// Every script, in registration order.
    pub fn all(&self) -> &[ScriptInfo] {
        &self.scripts
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_name_belongs_to_one_loaded_plugin_and_its_owner_may_register_it_again() {
        let mut registry = ScriptRegistry::default();
        let loaded = |_: &str| true;
        registry
            .register("a", "Rotator", serde_json::json!({"speed": 1}), loaded)
            .unwrap();
        let taken = registry
            .register("b", "Rotator", serde_json::Value::Null, loaded)
            .unwrap_err();
        assert!(taken
            .to_string()
            .contains("already registered by plugin `a`"));
        registry
            .register("a", "Rotator", serde_json::json!({"speed": 2}), loaded)
            .unwrap();
        assert_eq!(registry.all().len(), 1);
        assert_eq!(registry.get("Rotator").unwrap().default_params["speed"], 2);
        // Once `a` is gone, `b` may take the name.
        registry
            .register("b", "Rotator", serde_json::Value::Null, |_| false)
            .unwrap();
        assert_eq!(registry.get("Rotator").unwrap().plugin, "b");
        registry.remove_plugin("b");
        assert!(registry.all().is_empty());
    }
}
