//! [`PluginModule`]: the root module every plugin library exports, and the glue
//! `export_plugin!` expands to.

#![allow(missing_docs)]

use abi_stable::{
    declare_root_module_statics,
    library::RootModule,
    package_version_strings,
    sabi_types::VersionStrings,
    std_types::{RResult, RStr},
    StableAbi,
};

use super::{CallFailure, PluginBox};

/// The root module of a plugin library. A prefix type: fields may only be appended.
#[repr(C)]
#[derive(StableAbi)]
#[sabi(kind(Prefix(prefix_ref = PluginModuleRef)))]
#[sabi(missing_field(panic))]
pub struct PluginModule {
    /// The plugin crate's name (`CARGO_CRATE_NAME`: `-` becomes `_`).
    pub plugin_name: RStr<'static>,
    /// The plugin crate's version (`CARGO_PKG_VERSION`).
    pub plugin_version: RStr<'static>,
    /// Builds a fresh plugin object.
    #[sabi(last_prefix_field)]
    pub new_plugin: extern "C" fn() -> RResult<PluginBox, CallFailure>,
}

impl RootModule for PluginModuleRef {
    declare_root_module_statics! {PluginModuleRef}
    const BASE_NAME: &'static str = "onyx_plugin";
    const NAME: &'static str = "onyx plugin";
    const VERSION_STRINGS: VersionStrings = package_version_strings!();
}

/// The exported symbol name that `#[export_root_module]` would generate. `export_plugin!`
/// must spell it as a literal; a test keeps the two equal.
pub const ROOT_SYMBOL: &str = "_1as_0lib_1header_0root_bmodule_bloader";

#[cfg(test)]
mod tests {
    #[test]
    fn root_symbol_matches_abi_stable() {
        assert_eq!(
            super::ROOT_SYMBOL,
            abi_stable::library::ROOT_MODULE_LOADER_NAME
        );
    }
}
