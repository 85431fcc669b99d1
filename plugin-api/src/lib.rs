//! # onyx-plugin-api
//!
//! The one crate an Onyx plugin depends on. Implement [`Plugin`], export it with
//! [`export_plugin!`], build the crate as a `cdylib`, and the Onyx host loads it at run time.
//!
//! ```
//! use onyx_plugin_api::{export_plugin, Ctx, Entity, Name, Plugin, Transform};
//!
//! /// Lifts a crate by one metre per second.
//! #[derive(Default)]
//! struct Lift {
//!     crate_: Option<Entity>,
//! }
//!
//! impl Plugin for Lift {
//!     fn on_init(&mut self, ctx: &mut Ctx) {
//!         self.crate_ = ctx.spawn((Name::new("crate"), Transform::IDENTITY)).ok();
//!     }
//!
//!     fn on_fixed_update(&mut self, ctx: &mut Ctx) {
//!         let Some(entity) = self.crate_ else { return };
//!         let dt = ctx.time().fixed_delta;
//!         if let Ok(mut t) = ctx.get::<Transform>(entity) {
//!             t.translation.y += 1.0 * dt;
//!             ctx.set(entity, t).ok();
//!         }
//!     }
//! }
//!
//! export_plugin!(Lift);
//!
//! // Test it in a headless host (crate `onyx-runtime`), through the same ABI adapter:
//! let mut host = onyx_runtime::HeadlessHost::new();
//! host.add_plugin("lift", Lift::default()).unwrap();
//! host.step(60); // one second at the default 60 Hz
//! let (_, t) = host.find::<Transform>("crate").unwrap();
//! assert!((t.translation.y - 1.0).abs() < 1e-4);
//! ```
//!
//! ## Map
//!
//! - [`Plugin`] (`plugin.rs`): the lifecycle; [`export_plugin!`] (`export.rs`) exports it.
//! - [`Ctx`] (`ctx.rs`): the host during a call — entities, components, bulk queries,
//!   time, input, events, logging, quit. Its errors: [`CtxError`] (`ctx_error.rs`).
//! - `component/`: the built-in components ([`Name`], [`Transform`], [`Parent`],
//!   [`MeshRenderer`], [`Camera`], [`Light`], [`RigidBody`], [`Collider`] — each defined once,
//!   see [`Builtin`]), your own [`Component`]s, [`Bundle`]s, and [`GlobalTransform`], the
//!   world pose the host computes.
//! - `event/`: [`Event`] and its sources; [`Message`] for typed custom events.
//! - `input/`: [`Key`], [`MouseButton`], [`InputState`].
//! - `physics/`: [`QueryFilter`] for overlap queries and shape casts, [`CharacterController`]
//!   and [`CharacterMove`] for kinematic characters.
//! - [`Time`] (`time.rs`), [`Flow`] (`flow.rs`), [`LogLevel`] (`log_level.rs`),
//!   [`state`] (save/load helpers for hot reload).
//! - [`tools`]: what tools (the editor) read through `Ctx`: entity lists, components as
//!   JSON, plugins, diagnostics, console lines, play mode, [`Script`]s, view switches.
//! - [`gui`]: egui across the boundary — [`Plugin::draw_gui`] gets a root [`egui::Ui`];
//!   [`gui::VIEWPORT_TEXTURE`] / [`gui::viewport`] show the scene inside the UI.
//! - [`host`]: for the host runtime only (loading libraries, serving `Ctx`).
//!
//! ## Conventions
//!
//! Y is up, coordinates are right-handed, lengths in metres, angles in radians, time in
//! seconds. Math types are [`glam`]'s, re-exported.
//!
//! ## The boundary
//!
//! Plugins and the host are separate binaries built at different times, so every value that
//! crosses between them is plain `#[repr(C)]` data whose layout [abi_stable] checks when the
//! library is opened. A plugin built against an incompatible version of this crate is
//! refused with a message, never run. All of that stays inside this crate: plugin code is
//! plain Rust.
//!
//! [abi_stable]: https://docs.rs/abi_stable

#![warn(missing_docs)]

pub mod component;
mod ctx;
mod ctx_error;
mod entity;
pub mod event;
mod export;
mod flow;
pub mod gui;
pub mod host;
pub mod input;
mod log_level;
mod physics;
mod plugin;
pub mod state;
mod time;
pub mod tools;

/// The README's examples, compiled as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../README.md")]
struct ReadmeDoctests;

#[doc(hidden)]
#[path = "ffi/mod.rs"]
pub mod __ffi;

pub use component::*;
pub use ctx::Ctx;
pub use ctx_error::{CtxError, ParentProblem};
pub use egui;
pub use entity::Entity;
pub use event::*;
pub use flow::Flow;
pub use glam;
pub use input::*;
pub use log_level::LogLevel;
pub use physics::{CharacterController, CharacterMove, QueryFilter};
pub use plugin::{AttachInfo, Plugin, PluginError};
pub use time::Time;
pub use tools::{PlayMode, Script, ScriptCall, ScriptPhase};
