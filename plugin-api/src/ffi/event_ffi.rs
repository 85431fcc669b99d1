//! [`EventFfi`]: an [`Event`] borrowed as plain data for the boundary.

use abi_stable::{
    std_types::{RSlice, RStr},
    StableAbi,
};

use crate::{
    CustomEvent, Entity, Event, GraphicsEvent, InputEvent, Key, MouseButton, PhysicsEvent,
    PlatformEvent, WindowEvent,
};

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
    GpuError {
        message: RStr<'a>,
    },
    DeviceLost {
        message: RStr<'a>,
    },
    AssetFailed {
        path: RStr<'a>,
        message: RStr<'a>,
    },
    ContactStarted {
        a: Entity,
        b: Entity,
        normal: [f32; 3],
        point: [f32; 3],
        impulse: f32,
    },
    ContactEnded {
        a: Entity,
        b: Entity,
    },
    SensorEntered {
        sensor: Entity,
        other: Entity,
    },
    SensorExited {
        sensor: Entity,
        other: Entity,
    },
    JointBroke {
        entity: Entity,
        force: [f32; 3],
        torque: [f32; 3],
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
            Event::Graphics(GraphicsEvent::Gpu { message }) => EventFfi::GpuError {
                message: message.as_str().into(),
            },
            Event::Graphics(GraphicsEvent::DeviceLost { message }) => EventFfi::DeviceLost {
                message: message.as_str().into(),
            },
            Event::Graphics(GraphicsEvent::AssetFailed { path, message }) => {
                EventFfi::AssetFailed {
                    path: path.as_str().into(),
                    message: message.as_str().into(),
                }
            }
            Event::Physics(PhysicsEvent::ContactStarted {
                a,
                b,
                normal,
                point,
                impulse,
            }) => EventFfi::ContactStarted {
                a: *a,
                b: *b,
                normal: normal.to_array(),
                point: point.to_array(),
                impulse: *impulse,
            },
            Event::Physics(PhysicsEvent::ContactEnded { a, b }) => {
                EventFfi::ContactEnded { a: *a, b: *b }
            }
            Event::Physics(PhysicsEvent::SensorEntered { sensor, other }) => {
                EventFfi::SensorEntered {
                    sensor: *sensor,
                    other: *other,
                }
            }
            Event::Physics(PhysicsEvent::SensorExited { sensor, other }) => {
                EventFfi::SensorExited {
                    sensor: *sensor,
                    other: *other,
                }
            }
            Event::Physics(PhysicsEvent::JointBroke {
                entity,
                force,
                torque,
            }) => EventFfi::JointBroke {
                entity: *entity,
                force: force.to_array(),
                torque: torque.to_array(),
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
            EventFfi::GpuError { message } => GraphicsEvent::Gpu {
                message: s(message),
            }
            .into(),
            EventFfi::DeviceLost { message } => GraphicsEvent::DeviceLost {
                message: s(message),
            }
            .into(),
            EventFfi::AssetFailed { path, message } => GraphicsEvent::AssetFailed {
                path: s(path),
                message: s(message),
            }
            .into(),
            EventFfi::ContactStarted {
                a,
                b,
                normal,
                point,
                impulse,
            } => PhysicsEvent::ContactStarted {
                a,
                b,
                normal: normal.into(),
                point: point.into(),
                impulse,
            }
            .into(),
            EventFfi::ContactEnded { a, b } => PhysicsEvent::ContactEnded { a, b }.into(),
            EventFfi::SensorEntered { sensor, other } => {
                PhysicsEvent::SensorEntered { sensor, other }.into()
            }
            EventFfi::SensorExited { sensor, other } => {
                PhysicsEvent::SensorExited { sensor, other }.into()
            }
            EventFfi::JointBroke {
                entity,
                force,
                torque,
            } => PhysicsEvent::JointBroke {
                entity,
                force: force.into(),
                torque: torque.into(),
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
            GraphicsEvent::Gpu {
                message: "v".into(),
            }
            .into(),
            GraphicsEvent::DeviceLost {
                message: "l".into(),
            }
            .into(),
            GraphicsEvent::AssetFailed {
                path: "p".into(),
                message: "m".into(),
            }
            .into(),
            PhysicsEvent::ContactStarted {
                a: Entity::from_bits(1),
                b: Entity::from_bits(2),
                normal: glam::Vec3::Y,
                point: glam::Vec3::ONE,
                impulse: 2.5,
            }
            .into(),
            PhysicsEvent::ContactEnded {
                a: Entity::from_bits(2),
                b: Entity::from_bits(1),
            }
            .into(),
            PhysicsEvent::SensorEntered {
                sensor: Entity::from_bits(3),
                other: Entity::from_bits(4),
            }
            .into(),
            PhysicsEvent::SensorExited {
                sensor: Entity::from_bits(4),
                other: Entity::from_bits(3),
            }
            .into(),
            PhysicsEvent::JointBroke {
                entity: Entity::from_bits(5),
                force: glam::Vec3::new(60.0, 0.0, 0.0),
                torque: glam::Vec3::Z,
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
