//! [`export_plugin!`](crate::export_plugin): turns a type implementing
//! [`Plugin`](crate::Plugin) into a loadable plugin library.

/// Exports a [`Plugin`](crate::Plugin) type as this library's Onyx plugin.
///
/// ```
/// #[derive(Default)]
/// struct MyPlugin {
///     speed: f32,
/// }
/// impl onyx_plugin_api::Plugin for MyPlugin {}
///
/// onyx_plugin_api::export_plugin!(MyPlugin); // built with Default
/// ```
///
/// or, to build it with an expression, and/or to name it explicitly (the name identifies the
/// plugin across hot reloads, in `--set`, in fault reports; by default it is the crate's name):
///
/// ```
/// # struct MyPlugin { speed: f32 }
/// # impl onyx_plugin_api::Plugin for MyPlugin {}
/// onyx_plugin_api::export_plugin!(MyPlugin, MyPlugin { speed: 2.0 }, name = "my_plugin");
/// ```
///
/// The crate must be built as a `cdylib` (add `"rlib"` too, to test it in-process). The
/// plugin's name is the crate's name with `-` written `_` (as in its library file name).
/// One plugin per library.
///
/// The macro defines the library's exported root symbol, so one executable can link at most
/// one plugin crate: a plugin's own tests use its rlib in-process, and load any other plugin
/// from its library file (`HeadlessHost::load_plugin`).
///
/// What it generates: the ABI-stable root module the host looks up, with the plugin crate's
/// name and version and a constructor; the plugin object that forwards each lifecycle call to
/// your type inside `catch_unwind`. A panic becomes an error value that the host reports.
#[macro_export]
macro_rules! export_plugin {
    ($plugin:ty) => {
        $crate::export_plugin!($plugin, <$plugin as ::core::default::Default>::default());
    };
    ($plugin:ty, name = $name:literal) => {
        $crate::export_plugin!(
            $plugin,
            <$plugin as ::core::default::Default>::default(),
            name = $name
        );
    };
    ($plugin:ty, $make:expr) => {
        $crate::export_plugin!($plugin, $make, name = ::core::env!("CARGO_CRATE_NAME"));
    };
    ($plugin:ty, $make:expr, name = $name:expr) => {
        #[doc(hidden)]
        #[unsafe(export_name = "_1as_0lib_1header_0root_bmodule_bloader")]
        pub static __ONYX_PLUGIN_ROOT_MODULE: $crate::__ffi::LibHeader = {
            extern "C" fn onyx_new_plugin(
            ) -> $crate::__ffi::RResult<$crate::__ffi::PluginBox, $crate::__ffi::CallFailure> {
                $crate::__ffi::new_plugin_box::<$plugin>($name, || $make)
            }
            fn onyx_root_module() -> $crate::__ffi::PluginModuleRef {
                use $crate::__ffi::PrefixTypeTrait;
                $crate::__ffi::PluginModule {
                    plugin_name: $crate::__ffi::RStr::from_str($name),
                    plugin_version: $crate::__ffi::RStr::from_str(::core::env!(
                        "CARGO_PKG_VERSION"
                    )),
                    new_plugin: onyx_new_plugin,
                }
                .leak_into_prefix()
            }
            extern "C" fn onyx_erased_root_module() -> $crate::__ffi::RootModuleResult {
                $crate::__ffi::__call_root_module_loader(onyx_root_module)
            }
            // SAFETY: the constructor returns the erased `PluginModuleRef` built above, which
            // is what `from_constructor::<PluginModuleRef>` requires.
            unsafe {
                $crate::__ffi::LibHeader::from_constructor::<$crate::__ffi::PluginModuleRef>(
                    onyx_erased_root_module,
                    $crate::__ffi::CheckTypeLayout::Yes,
                )
            }
        };
    };
}
