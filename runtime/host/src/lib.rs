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
//! - `window/`: the winit window and input mapping.

#![warn(missing_docs)]

pub mod clock;
mod headless_host;
mod host;
mod host_config;
mod host_reload;
pub mod physics;
pub mod plugins;
pub mod render;
pub mod scene;
pub mod state_dump;
pub mod window;
pub mod world;

pub use headless_host::HeadlessHost;
pub use host::{FrameReport, Host};
pub use host_config::HostConfig;
pub use plugins::{PluginLoadError, PluginStatus, ReloadError};
pub use scene::SceneError;
