//! The plugin boundary's plain-data side: every `#[repr(C)]`, `R*` and `extern "C"` item
//! lives here and nowhere else. Plugin authors and the runtime never use it directly.
//!
//! - `root_module.rs`: the exported root module and its symbol.
//! - `plugin_object.rs`: the plugin as a `#[sabi_trait]` object, with the panic-catching adapter.
//! - `gui_ffi.rs`, `plugin_gui.rs`: a GUI frame as plain data, and the plugin's own egui
//!   context that turns input into meshes and textures inside the plugin's image.
//! - `host_object.rs`: the host as a `#[sabi_trait]` object, built from `HostServices`.
//! - `tool_values.rs`: the tool services' entity list and call selectors.
//! - `values.rs`, `event_ffi.rs`, `attach_info_ffi.rs`, `ctx_error_ffi.rs`, `call_failure.rs`:
//!   the values that cross, with conversions to and from plain Rust.

#![allow(missing_docs)]

mod attach_info_ffi;
mod call_failure;
mod ctx_error_ffi;
mod event_ffi;
mod gui_ffi;
mod host_object;
mod plugin_gui;
mod plugin_object;
mod root_module;
mod script_call_ffi;
mod tool_bridge;
mod tool_values;
mod values;

pub use attach_info_ffi::AttachInfoFfi;
pub use call_failure::{CallFailure, FailureKind};
pub use ctx_error_ffi::{CtxErrorFfi, CtxErrorKind};
pub use event_ffi::EventFfi;
pub use gui_ffi::{GuiInputFfi, GuiOutputFfi, MeshFfi, TextureIdFfi, TextureSetFfi, VertexFfi};
pub use host_object::{
    with_ctx, CharacterMoveFfi, CharacterStepFfi, HostBridge, HostObject, HostObject_TO, HostRef,
    PluginOpFfi, QueryFilterFfi, RayFfi, SweepFfi,
};
pub use plugin_gui::{mark_no_gui, PluginGui};
pub use plugin_object::{
    catch, new_plugin_box, PluginAdapter, PluginBox, PluginObject, PluginObject_TO,
};
pub use root_module::{PluginModule, PluginModuleRef, ROOT_SYMBOL};
pub use script_call_ffi::ScriptCallFfi;
pub use tool_values::{BoundsFfi, EntityListFfi, ReportFfi, SceneOpFfi, ScreenPointFfi};
pub use values::{
    BlobFfi, BuiltinFfi, ComponentsFfi, EntityBlobFfi, GlobalTransformFfi, NameFfi, TransformFfi,
};

// What `export_plugin!` expands to, reached through `$crate`.
pub use abi_stable::library::{
    __call_root_module_loader, CheckTypeLayout, LibHeader, RootModuleResult,
};
pub use abi_stable::prefix_type::PrefixTypeTrait;
pub use abi_stable::std_types::{RResult, RStr};
