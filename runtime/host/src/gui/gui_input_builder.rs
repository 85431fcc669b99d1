//! [`GuiInputBuilder`]: gathers one frame of egui input from the host's input events (or
//! takes it whole from the window's egui-winit state).

use egui::{Event, Modifiers, Pos2, RawInput, Rect, Vec2};
use onyx_plugin_api::{InputEvent, Key};

use super::egui_keys::{egui_button, egui_key};

/// The size of the GUI screen before the window (or a test) says otherwise, pixels.
pub const DEFAULT_SCREEN_SIZE: (u32, u32) = (1280, 720);

/// Builds each frame's `egui::RawInput`.
#[derive(Debug)]
pub struct GuiInputBuilder {
    events: Vec<Event>,
    modifiers: Modifiers,
    pointer: Option<Pos2>,
    screen_size: (u32, u32),
    pixels_per_point: f32,
    focused: bool,
    external: Option<RawInput>,
}

impl Default for GuiInputBuilder {
    fn default() -> Self {
        Self {
            events: Vec::new(),
            modifiers: Modifiers::NONE,
            pointer: None,
            screen_size: DEFAULT_SCREEN_SIZE,
            pixels_per_point: 1.0,
            focused: true,
            external: None,
        }
    }
}

impl GuiInputBuilder {
    /// Folds one host input event into this frame's egui events.
    pub fn push(&mut self, event: &InputEvent) {
        match event {
            InputEvent::Key {
                key,
                pressed,
                repeat,
            } => {
                self.track_modifier(*key, *pressed);
                if let Some(egui_key) = egui_key(*key) {
                    self.events.push(Event::Key {
                        key: egui_key,
                        physical_key: Some(egui_key),
                        pressed: *pressed,
                        repeat: *repeat,
                        modifiers: self.modifiers,
                    });
                }
            }
            InputEvent::MouseButton { button, pressed } => {
                if let (Some(button), Some(pos)) = (egui_button(*button), self.pointer) {
                    self.events.push(Event::PointerButton {
                        pos,
                        button,
                        pressed: *pressed,
                        modifiers: self.modifiers,
                    });
                }
            }
            InputEvent::CursorMoved { x, y } => {
                let pos = Pos2::new(*x, *y) / self.pixels_per_point;
                self.pointer = Some(pos);
                self.events.push(Event::PointerMoved(pos));
            }
            InputEvent::Scroll { dx, dy } => self.events.push(Event::MouseWheel {
                unit: egui::MouseWheelUnit::Line,
                delta: Vec2::new(*dx, *dy),
                phase: egui::TouchPhase::Move,
                modifiers: self.modifiers,
            }),
            InputEvent::Text(text) => {
                if !self.modifiers.ctrl && !self.modifiers.command {
                    self.events.push(Event::Text(text.clone()));
                }
            }
            InputEvent::MouseMotion { .. } => {}
        }
    }

    /// Keeps the held modifiers and tells egui when they change (its `i.modifiers`: Ctrl held
    /// through a drag, Ctrl+Z).
    fn track_modifier(&mut self, key: Key, pressed: bool) {
        let before = self.modifiers;
        match key {
            Key::ShiftLeft | Key::ShiftRight => self.modifiers.shift = pressed,
            Key::ControlLeft | Key::ControlRight => {
                self.modifiers.ctrl = pressed;
                self.modifiers.command = pressed;
            }
            Key::AltLeft | Key::AltRight => self.modifiers.alt = pressed,
            _ => {}
        }
        if self.modifiers != before {
            self.events.push(Event::ModifiersChanged(self.modifiers));
        }
    }

    /// The window lost (or got) focus: egui releases what it holds.
    pub fn set_focused(&mut self, focused: bool) {
        self.focused = focused;
        self.events.push(Event::WindowFocused(focused));
        if !focused {
            self.modifiers = Modifiers::NONE;
        }
    }

    /// The drawable area, physical pixels.
    pub fn set_screen_size(&mut self, width: u32, height: u32) {
        self.screen_size = (width, height);
    }

    /// The drawable area, physical pixels.
    pub fn screen_size(&self) -> (u32, u32) {
        self.screen_size
    }

    /// Physical pixels per egui point (the window's scale factor).
    pub fn set_pixels_per_point(&mut self, pixels_per_point: f32) {
        if pixels_per_point.is_finite() && pixels_per_point > 0.0 {
            self.pixels_per_point = pixels_per_point;
        }
    }

    /// Physical pixels per egui point.
    pub fn pixels_per_point(&self) -> f32 {
        self.pixels_per_point
    }

    /// Where the pointer is, points (`None` before it first moves).
    pub fn pointer(&self) -> Option<Pos2> {
        self.pointer
    }

    /// Uses `raw` (from the window's egui-winit state: clipboard, IME, modifiers as the
    /// platform reports them) as the next frame's input instead of what was built here.
    pub fn set_external(&mut self, raw: RawInput) {
        self.external = Some(raw);
    }

    /// Drops this frame's input (no plugin draws a GUI to take it).
    pub fn discard(&mut self) {
        self.events.clear();
        self.external = None;
    }

    /// The input of the frame at `time` seconds that lasted `dt`; starts the next frame.
    pub fn take(&mut self, time: f64, dt: f32) -> RawInput {
        let events = std::mem::take(&mut self.events);
        if let Some(mut raw) = self.external.take() {
            raw.time = Some(time);
            raw.predicted_dt = dt;
            super::input_sanitizer::sanitize(&mut raw);
            return raw;
        }
        let size =
            Vec2::new(self.screen_size.0 as f32, self.screen_size.1 as f32) / self.pixels_per_point;
        let mut raw = RawInput {
            screen_rect: Some(Rect::from_min_size(Pos2::ZERO, size)),
            time: Some(time),
            predicted_dt: dt,
            events,
            focused: self.focused,
            ..RawInput::default()
        };
        if let Some(viewport) = raw.viewports.get_mut(&raw.viewport_id) {
            viewport.native_pixels_per_point = Some(self.pixels_per_point);
        } else {
            raw.viewports.insert(
                raw.viewport_id,
                egui::ViewportInfo {
                    native_pixels_per_point: Some(self.pixels_per_point),
                    ..Default::default()
                },
            );
        }
        super::input_sanitizer::sanitize(&mut raw);
        raw
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use onyx_plugin_api::MouseButton;

    #[test]
    fn a_click_becomes_a_pointer_button_at_the_last_cursor_position_in_points() {
        let mut builder = GuiInputBuilder::default();
        builder.set_pixels_per_point(2.0);
        builder.push(&InputEvent::CursorMoved { x: 100.0, y: 40.0 });
        builder.push(&InputEvent::MouseButton {
            button: MouseButton::Left,
            pressed: true,
        });
        let raw = builder.take(1.0, 1.0 / 60.0);
        assert_eq!(raw.events.len(), 2);
        assert!(matches!(
            raw.events[1],
            Event::PointerButton { pos, button: egui::PointerButton::Primary, pressed: true, .. }
                if pos == Pos2::new(50.0, 20.0)
        ));
        let screen = raw.screen_rect.map(|r| r.size());
        assert_eq!(screen, Some(Vec2::new(640.0, 360.0)));
        assert!(
            builder.take(2.0, 0.1).events.is_empty(),
            "events are taken once"
        );
    }
}
