//! # onyx-runtime
//!
//! The Onyx host: it owns the world (hecs), time, event dispatch and the window, and runs
//! plugins loaded from `cdylib` libraries. The `onyx` binary is its command line.
//!
//! ```
//! use onyx_runtime::HeadlessHost;
//!
//! let mut host = HeadlessHost::new();
//! // host.load_plugin("spinner")?;     // a plugin library, by name or path
//! host.step(60);                         // one second at 60 Hz
//! assert_eq!(host.host().time().ticks, 60);
//! ```
//!
//! ## Map
//!
//! - [`Host`] (`host.rs`): the frame loop and plugin lifecycle; [`HostConfig`];
//!   `host_reload.rs` (hot reload), `host_tools.rs` and `host_scripts.rs` (the tool
//!   services' and scripts' places in the frame).
//! - [`HeadlessHost`] (`headless_host.rs`): no window, no GPU — for tests.
//! - `state/`: the host's state in parts — the world, the frame's I/O, the subsystems.
//! - `world/`: entities and components (the built-ins through the one list), the scene
//!   graph and the assets; `hierarchy/`: parents, children and world poses.
//! - `services/`: what a plugin's `Ctx` reaches (`HostServices` and `ToolServices`).
//! - `clock/`: the fixed-step [`FixedClock`](clock::FixedClock) and its settings.
//! - `plugins/`: search path, loading through fresh copies, load errors, fault handling.
//! - `scene/`: RON scene files (parents by file-local id), atomic saves.
//! - `state_dump.rs`: the `--dump-state` JSON.
//! - `physics/`: onyx-physics driven by `RigidBody`/`Collider` components in each fixed step.
//! - `render/`: the world drawn with onyx-render (interpolated world poses, cameras, lights).
//! - `assets/`: mesh and texture ids ↔ files; `fs/`: atomic writes and file watching.
//! - `gui/`: plugin GUIs — egui input in, meshes and textures out, painted over the scene.
//! - `window/`: the winit window and input mapping.
//! - `watchdog/`: which plugin call each thread is in; the watchdog thread for calls that do
//!   not return; the crash report for native failures.
//! - Tool services (the editor's): `console/` (log ring buffer + tracing layer),
//!   `diagnostics/` (frame and per-plugin timings), `play_mode/` (edit/play/pause/stop with a
//!   world snapshot), `scripts/` (registered behaviours run per entity), `tools/` (what they
//!   keep between calls).
//!
//! The modules form layers: none imports one that imports it back (a test checks).

#![warn(missing_docs)]

pub mod animation;
pub(crate) mod assets;
pub mod clock;
pub mod console;
pub(crate) mod diagnostics;
pub(crate) mod entity_id;
pub(crate) mod entity_map;
pub mod fs;
pub mod gui;
mod headless_host;
pub mod hierarchy;
mod host;
mod host_config;
mod host_reload;
mod host_scripts;
mod host_tools;
pub mod physics;
pub(crate) mod play_mode;
pub mod plugins;
pub mod render;
pub mod scene;
pub(crate) mod scripts;
pub(crate) mod services;
pub(crate) mod stage;
pub(crate) mod state;
pub(crate) mod state_dump;
pub(crate) mod tools;
pub mod watchdog;
pub mod window;
pub mod world;

pub use assets::AssetRegistry;
pub use headless_host::HeadlessHost;
pub use host::{FrameReport, Host, SCREENSHOT_LOAD_TIMEOUT};
pub use host_config::{HostConfig, DEFAULT_MAX_EVENTS_PER_FRAME};
pub use onyx_physics::PhysicsPreset;
pub use physics::ScenePhysics;
pub use plugins::{PluginLoadError, PluginStatus, ReloadError};
pub use scene::SceneError;
