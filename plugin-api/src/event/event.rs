//! [`Event`]: everything the dispatcher delivers to [`Plugin::on_event`](crate::Plugin::on_event).

use crate::{CustomEvent, GraphicsEvent, InputEvent, PhysicsEvent, PlatformEvent, WindowEvent};

/// One event, tagged by its source. Events raised during frame N are delivered at the start
/// of frame N + 1, to every running plugin in load order.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Event {
    /// From the window: resize, focus, close.
    Window(WindowEvent),
    /// From the keyboard and mouse.
    Input(InputEvent),
    /// From the host itself: plugins loaded or faulted, errors.
    Platform(PlatformEvent),
    /// From the renderer: GPU errors, device loss, assets that failed to load.
    Graphics(GraphicsEvent),
    /// From physics: contacts started and ended.
    Physics(PhysicsEvent),
    /// Sent by a plugin with [`Ctx::send`](crate::Ctx::send).
    Custom(CustomEvent),
}

impl From<WindowEvent> for Event {
    fn from(event: WindowEvent) -> Self {
        Self::Window(event)
    }
}

impl From<InputEvent> for Event {
    fn from(event: InputEvent) -> Self {
        Self::Input(event)
    }
}

impl From<PlatformEvent> for Event {
    fn from(event: PlatformEvent) -> Self {
        Self::Platform(event)
    }
}

impl From<GraphicsEvent> for Event {
    fn from(event: GraphicsEvent) -> Self {
        Self::Graphics(event)
    }
}

impl From<PhysicsEvent> for Event {
    fn from(event: PhysicsEvent) -> Self {
        Self::Physics(event)
    }
}

impl From<CustomEvent> for Event {
    fn from(event: CustomEvent) -> Self {
        Self::Custom(event)
    }
}
