//! [`EventFfi`]: an [`Event`] borrowed as plain data for the boundary.

use abi_stable::{
    std_types::{RSlice, RStr},
    StableAbi,
};

use crate::{CustomEvent, Event, InputEvent, Key, MouseButton, PlatformEvent, WindowEvent};

#[repr(C, u8)]
#[derive(StableAbi, Clone, Copy, Debug)]
pub enum EventFfi<'a> {
    Resized {
        width: u32,
        height: u32,
    },
    Focused(bool),
    CloseRequested,
    Key {
        key: Key,
        pressed: bool,
        repeat: bool,
    },
    MouseButton {
        button: MouseButton,
        pressed: bool,
    },
    CursorMoved {
        x: f32,
        y: f32,
    },
    MouseMotion {
        dx: f32,
        dy: f32,
    },
    Scroll {
        dx: f32,
        dy: f32,
    },
    Text(RStr<'a>),
    PluginLoaded {
        plugin: RStr<'a>,
    },
    PluginFaulted {
        plugin: RStr<'a>,
        stage: RStr<'a>,
        message: RStr<'a>,
    },
    PluginReloaded {
        plugin: RStr<'a>,
    },
    PluginReloadFailed {
        plugin: RStr<'a>,
        message: RStr<'a>,
    },
    PluginUnloaded {
        plugin: RStr<'a>,
    },
    Error {
        message: RStr<'a>,
    },
    Custom {
        name: RStr<'a>,
        sender: RStr<'a>,
        payload: RSlice<'a, u8>,
    },
}

impl<'a> From<&'a Event> for EventFfi<'a> {
    fn from(event: &'a Event) -> Self {
        match event {
            Event::Window(WindowEvent::Resized { width, height }) => EventFfi::Resized {
                width: *width,
                height: *height,
            },
            Event::Window(WindowEvent::Focused(f)) => EventFfi::Focused(*f),
            Event::Window(WindowEvent::CloseRequested) => EventFfi::CloseRequested,
            Event::Input(InputEvent::Key {
                key,
                pressed,
                repeat,
            }) => EventFfi::Key {
                key: *key,
                pressed: *pressed,
                repeat: *repeat,
            },
            Event::Input(InputEvent::MouseButton { button, pressed }) => EventFfi::MouseButton {
                button: *button,
                pressed: *pressed,
            },
            Event::Input(InputEvent::CursorMoved { x, y }) => {
                EventFfi::CursorMoved { x: *x, y: *y }
            }
            Event::Input(InputEvent::MouseMotion { dx, dy }) => {
                EventFfi::MouseMotion { dx: *dx, dy: *dy }
            }
            Event::Input(InputEvent::Scroll { dx, dy }) => EventFfi::Scroll { dx: *dx, dy: *dy },
            Event::Input(InputEvent::Text(text)) => EventFfi::Text(text.as_str().into()),
            Event::Platform(PlatformEvent::PluginLoaded { plugin }) => EventFfi::PluginLoaded {
                plugin: plugin.as_str().into(),
            },
            Event::Platform(PlatformEvent::PluginFaulted {
                plugin,
                stage,
                message,
            }) => EventFfi::PluginFaulted {
                plugin: plugin.as_str().into(),
                stage: stage.as_str().into(),
                message: message.as_str().into(),
            },
            Event::Platform(PlatformEvent::PluginReloaded { plugin }) => EventFfi::PluginReloaded {
                plugin: plugin.as_str().into(),
            },
            Event::Platform(PlatformEvent::PluginReloadFailed { plugin, message }) => {
                EventFfi::PluginReloadFailed {
                    plugin: plugin.as_str().into(),
                    message: message.as_str().into(),
                }
            }
            Event::Platform(PlatformEvent::PluginUnloaded { plugin }) => EventFfi::PluginUnloaded {
                plugin: plugin.as_str().into(),
            },
            Event::Platform(PlatformEvent::Error { message }) => EventFfi::Error {
                message: message.as_str().into(),
            },
            Event::Custom(CustomEvent {
                name,
                sender,
                payload,
            }) => EventFfi::Custom {
                name: name.as_str().into(),
                sender: sender.as_str().into(),
                payload: payload.as_slice().into(),
            },
        }
    }
}

impl From<EventFfi<'_>> for Event {
    fn from(event: EventFfi<'_>) -> Self {
        let s = |s: RStr<'_>| s.as_str().to_owned();
        match event {
            EventFfi::Resized { width, height } => WindowEvent::Resized { width, height }.into(),
            EventFfi::Focused(f) => WindowEvent::Focused(f).into(),
            EventFfi::CloseRequested => WindowEvent::CloseRequested.into(),
            EventFfi::Key {
                key,
                pressed,
                repeat,
            } => InputEvent::Key {
                key,
                pressed,
                repeat,
            }
            .into(),
            EventFfi::MouseButton { button, pressed } => {
                InputEvent::MouseButton { button, pressed }.into()
            }
            EventFfi::CursorMoved { x, y } => InputEvent::CursorMoved { x, y }.into(),
            EventFfi::MouseMotion { dx, dy } => InputEvent::MouseMotion { dx, dy }.into(),
            EventFfi::Scroll { dx, dy } => InputEvent::Scroll { dx, dy }.into(),
            EventFfi::Text(text) => InputEvent::Text(s(text)).into(),
            EventFfi::PluginLoaded { plugin } => {
                PlatformEvent::PluginLoaded { plugin: s(plugin) }.into()
            }
            EventFfi::PluginFaulted {
                plugin,
                stage,
                message,
            } => PlatformEvent::PluginFaulted {
                plugin: s(plugin),
                stage: s(stage),
                message: s(message),
            }
            .into(),
            EventFfi::PluginReloaded { plugin } => {
                PlatformEvent::PluginReloaded { plugin: s(plugin) }.into()
            }
            EventFfi::PluginReloadFailed { plugin, message } => PlatformEvent::PluginReloadFailed {
                plugin: s(plugin),
                message: s(message),
            }
            .into(),
            EventFfi::PluginUnloaded { plugin } => {
                PlatformEvent::PluginUnloaded { plugin: s(plugin) }.into()
            }
            EventFfi::Error { message } => PlatformEvent::Error {
                message: s(message),
            }
            .into(),
            EventFfi::Custom {
                name,
                sender,
                payload,
            } => CustomEvent {
                name: s(name),
                sender: s(sender),
                payload: payload.to_vec(),
            }
            .into(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_event_survives_the_round_trip() {
        let events: Vec<Event> = vec![
            WindowEvent::Resized {
                width: 3,
                height: 4,
            }
            .into(),
            WindowEvent::Focused(false).into(),
            WindowEvent::CloseRequested.into(),
            InputEvent::Key {
                key: Key::Q,
                pressed: true,
                repeat: true,
            }
            .into(),
            InputEvent::MouseButton {
                button: MouseButton::Middle,
                pressed: false,
            }
            .into(),
            InputEvent::CursorMoved { x: 1.5, y: 2.5 }.into(),
            InputEvent::MouseMotion { dx: -1.0, dy: 1.0 }.into(),
            InputEvent::Scroll { dx: 0.0, dy: -2.0 }.into(),
            InputEvent::Text("é".into()).into(),
            PlatformEvent::PluginLoaded { plugin: "a".into() }.into(),
            PlatformEvent::PluginFaulted {
                plugin: "a".into(),
                stage: "on_update".into(),
                message: "boom".into(),
            }
            .into(),
            PlatformEvent::PluginReloaded { plugin: "b".into() }.into(),
            PlatformEvent::PluginReloadFailed {
                plugin: "b".into(),
                message: "m".into(),
            }
            .into(),
            PlatformEvent::PluginUnloaded { plugin: "b".into() }.into(),
            PlatformEvent::Error {
                message: "bad".into(),
            }
            .into(),
            CustomEvent {
                name: "n".into(),
                sender: "s".into(),
                payload: vec![1, 2, 3],
            }
            .into(),
        ];
        for event in events {
            assert_eq!(Event::from(EventFfi::from(&event)), event);
        }
    }
}
