//! Events, by source.
//!
//! - `event.rs`: [`Event`], the envelope `on_event` receives.
//! - `window_event.rs`, `input_event.rs`, `platform_event.rs`, `graphics_event.rs`, `physics_event.rs`: one enum
//!   per source.
//! - `custom_event.rs`: [`CustomEvent`] (received) and [`Message`] (typed payloads to send).

mod custom_event;
#[allow(clippy::module_inception)]
mod event;
mod graphics_event;
mod input_event;
mod physics_event;
mod platform_event;
mod window_event;

pub use custom_event::{CustomEvent, Message};
pub use event::Event;
pub use graphics_event::GraphicsEvent;
pub use input_event::InputEvent;
pub use physics_event::PhysicsEvent;
pub use platform_event::PlatformEvent;
pub use window_event::WindowEvent;
