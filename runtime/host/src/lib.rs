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
//! - [`Host`] (`host.rs`): the frame loop and plugin lifecycle; [`HostConfig`].
//! - [`HeadlessHost`] (`headless_host.rs`): no window, no GPU — for tests.
//! - `clock/`: the fixed-step [`FixedClock`](clock::FixedClock) and its settings.
//! - `plugins/`: search path, loading through fresh copies, load errors, fault handling.
//! - `world/`: the hecs world behind `Ctx` ([`CallContext`](world::CallContext)).
//! - `scene/`: RON scene files, atomic saves.
//! - `state_dump.rs`: the `--dump-state` JSON.
//! - `physics/`: onyx-physics driven by `RigidBody`/`Collider` components in each fixed step.
//! - `render/`: the world drawn with onyx-render (interpolated poses, cameras, lights, assets).
//! - `gui/`: plugin GUIs — egui input in, meshes and textures out, painted over the scene.
//! - `window/`: the winit window and input mapping.
//! - Tool services (the editor's): `console/` (log ring buffer + tracing layer),
//!   `diagnostics/` (frame and per-plugin timings), `play_mode/` (edit/play/pause/stop with a
//!   world snapshot), `scripts/` (registered behaviours run per entity), `host_tools.rs`
//!   (their place in the frame); `world/call_context_tools.rs` serves them to plugins.

#![warn(missing_docs)]

pub mod clock;
pub mod console;
pub mod diagnostics;
pub mod gui;
mod headless_host;
mod host;
mod host_config;
mod host_reload;
mod host_tools;
pub mod physics;
pub mod play_mode;
pub mod plugins;
pub mod render;
pub mod scene;
pub mod scripts;
pub mod state_dump;
pub mod window;
pub mod world;

pub use headless_host::HeadlessHost;
pub use host::{FrameReport, Host};
pub use host_config::HostConfig;
pub use onyx_physics::PhysicsPreset;
pub use plugins::{PluginLoadError, PluginStatus, ReloadError};
pub use scene::{SceneError, ScenePhysics};
