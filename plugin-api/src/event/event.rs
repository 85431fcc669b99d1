//! [`Event`]: everything the dispatcher delivers to [`Plugin::on_event`](crate::Plugin::on_event).

use crate::{CustomEvent, InputEvent, PlatformEvent, WindowEvent};

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

impl From<CustomEvent> for Event {
    fn from(event: CustomEvent) -> Self {
        Self::Custom(event)
    }
}
