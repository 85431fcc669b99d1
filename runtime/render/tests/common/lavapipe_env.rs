//! Pins wgpu to lavapipe (Vulkan, CPU) unless the caller already chose an adapter, and gives
//! Mesa a runtime dir. Shared by the integration tests (`common::setup`) and the benches
//! (`#[path]`-included), which need the same environment before wgpu starts.

/// Sets the defaults; variables the caller already set win.
pub fn pin_lavapipe() {
    let defaults = [
        ("WGPU_BACKEND", "vulkan"),
        ("WGPU_ADAPTER_NAME", "llvmpipe"),
    ];
    for (key, value) in defaults {
        if std::env::var_os(key).is_none() {
            std::env::set_var(key, value);
        }
    }
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        let dir = std::env::temp_dir().join("onyx-render-xdg");
        let _ = std::fs::create_dir_all(&dir);
        std::env::set_var("XDG_RUNTIME_DIR", dir);
    }
}
