//! [`InputState`]: keyboard and mouse state of the current frame.

use abi_stable::StableAbi;
use glam::Vec2;

use crate::{InputEvent, Key, MouseButton};

/// Number of key slots in the bitsets (must cover every [`Key`]).
pub(crate) const KEY_SLOTS: usize = 128;
const KEY_WORDS: usize = KEY_SLOTS / 64;

/// Which keys and buttons are held, which went down or up this frame, and where the cursor
/// is. Read it with [`Ctx::input`](crate::Ctx::input).
///
/// "Pressed" and "released" are edges: true only in the frame the change happened.
/// Cursor coordinates are in physical pixels from the window's top-left corner.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, Default, PartialEq)]
pub struct InputState {
    keys_down: [u64; KEY_WORDS],
    keys_pressed: [u64; KEY_WORDS],
    keys_released: [u64; KEY_WORDS],
    buttons_down: u8,
    buttons_pressed: u8,
    buttons_released: u8,
    #[sabi(unsafe_opaque_field)]
    cursor: Vec2,
    #[sabi(unsafe_opaque_field)]
    cursor_delta: Vec2,
    #[sabi(unsafe_opaque_field)]
    scroll: Vec2,
}

fn bit(bits: &[u64; KEY_WORDS], key: Key) -> bool {
    let i = key as usize;
    bits[i / 64] & (1 << (i % 64)) != 0
}

fn set_bit(bits: &mut [u64; KEY_WORDS], key: Key, on: bool) {
    let i = key as usize;
    if on {
        bits[i / 64] |= 1 << (i % 64);
    } else {
        bits[i / 64] &= !(1 << (i % 64));
    }
}

impl InputState {
    /// Whether `key` is held down.
    pub fn key_down(&self, key: Key) -> bool {
        bit(&self.keys_down, key)
    }

    /// Whether `key` went down this frame (key repeats do not count).
    pub fn key_pressed(&self, key: Key) -> bool {
        bit(&self.keys_pressed, key)
    }

    /// Whether `key` went up this frame.
    pub fn key_released(&self, key: Key) -> bool {
        bit(&self.keys_released, key)
    }

    /// Whether `button` is held down.
    pub fn mouse_down(&self, button: MouseButton) -> bool {
        self.buttons_down & (1 << button as u8) != 0
    }

    /// Whether `button` went down this frame.
    pub fn mouse_pressed(&self, button: MouseButton) -> bool {
        self.buttons_pressed & (1 << button as u8) != 0
    }

    /// Whether `button` went up this frame.
    pub fn mouse_released(&self, button: MouseButton) -> bool {
        self.buttons_released & (1 << button as u8) != 0
    }

    /// Cursor position in physical pixels from the window's top-left corner.
    pub fn cursor(&self) -> Vec2 {
        self.cursor
    }

    /// Raw mouse motion this frame (not limited by the window edge).
    pub fn cursor_delta(&self) -> Vec2 {
        self.cursor_delta
    }

    /// Scroll this frame, in lines (positive y scrolls up / away from the user).
    pub fn scroll(&self) -> Vec2 {
        self.scroll
    }

    /// Folds one input event into the state. The host calls this for every input event
    /// before dispatching it; plugins only read the result.
    pub fn apply(&mut self, event: &InputEvent) {
        match *event {
            InputEvent::Key {
                key,
                pressed,
                repeat,
            } => {
                if pressed && !repeat && !self.key_down(key) {
                    set_bit(&mut self.keys_pressed, key, true);
                }
                if !pressed && self.key_down(key) {
                    set_bit(&mut self.keys_released, key, true);
                }
                set_bit(&mut self.keys_down, key, pressed);
            }
            InputEvent::MouseButton { button, pressed } => {
                let mask = 1 << button as u8;
                if pressed && self.buttons_down & mask == 0 {
                    self.buttons_pressed |= mask;
                }
                if !pressed && self.buttons_down & mask != 0 {
                    self.buttons_released |= mask;
                }
                if pressed {
                    self.buttons_down |= mask;
                } else {
                    self.buttons_down &= !mask;
                }
            }
            InputEvent::CursorMoved { x, y } => self.cursor = Vec2::new(x, y),
            InputEvent::MouseMotion { dx, dy } => self.cursor_delta += Vec2::new(dx, dy),
            InputEvent::Scroll { dx, dy } => self.scroll += Vec2::new(dx, dy),
            InputEvent::Text(_) => {}
        }
    }

    /// Clears the per-frame edges and deltas. The host calls this at the end of each frame.
    pub fn end_frame(&mut self) {
        self.keys_pressed = [0; KEY_WORDS];
        self.keys_released = [0; KEY_WORDS];
        self.buttons_pressed = 0;
        self.buttons_released = 0;
        self.cursor_delta = Vec2::ZERO;
        self.scroll = Vec2::ZERO;
    }

    /// Releases every key and button (the window lost focus: no key-up will arrive).
    pub fn release_all(&mut self) {
        for word in 0..KEY_WORDS {
            self.keys_released[word] |= self.keys_down[word];
            self.keys_down[word] = 0;
        }
        self.buttons_released |= self.buttons_down;
        self.buttons_down = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(key: Key, pressed: bool) -> InputEvent {
        InputEvent::Key {
            key,
            pressed,
            repeat: false,
        }
    }

    #[test]
    fn press_is_an_edge_and_down_is_a_level() {
        let mut input = InputState::default();
        input.apply(&key(Key::W, true));
        assert!(input.key_down(Key::W) && input.key_pressed(Key::W));
        input.end_frame();
        assert!(input.key_down(Key::W) && !input.key_pressed(Key::W));
        input.apply(&key(Key::W, false));
        assert!(!input.key_down(Key::W) && input.key_released(Key::W));
        assert!(!input.key_down(Key::S), "other keys untouched");
    }

    #[test]
    fn keys_past_the_first_word_work() {
        let mut input = InputState::default();
        assert!(Key::Unknown as usize >= 64);
        input.apply(&key(Key::Unknown, true));
        assert!(input.key_down(Key::Unknown) && !input.key_down(Key::A));
    }

    #[test]
    fn repeats_do_not_count_as_presses() {
        let mut input = InputState::default();
        input.apply(&key(Key::Space, true));
        input.end_frame();
        input.apply(&InputEvent::Key {
            key: Key::Space,
            pressed: true,
            repeat: true,
        });
        assert!(input.key_down(Key::Space) && !input.key_pressed(Key::Space));
    }

    #[test]
    fn mouse_motion_and_scroll_accumulate_within_a_frame() {
        let mut input = InputState::default();
        input.apply(&InputEvent::MouseMotion { dx: 1.0, dy: 2.0 });
        input.apply(&InputEvent::MouseMotion { dx: 3.0, dy: -1.0 });
        input.apply(&InputEvent::Scroll { dx: 0.0, dy: 1.0 });
        input.apply(&InputEvent::MouseButton {
            button: MouseButton::Right,
            pressed: true,
        });
        assert_eq!(input.cursor_delta(), Vec2::new(4.0, 1.0));
        assert_eq!(input.scroll(), Vec2::new(0.0, 1.0));
        assert!(input.mouse_pressed(MouseButton::Right));
        input.end_frame();
        assert_eq!(input.cursor_delta(), Vec2::ZERO);
        assert!(input.mouse_down(MouseButton::Right) && !input.mouse_pressed(MouseButton::Right));
        input.release_all();
        assert!(!input.mouse_down(MouseButton::Right) && input.mouse_released(MouseButton::Right));
    }
}
