//! Onyx input values as egui's: keys and mouse buttons.

use onyx_plugin_api::{Key, MouseButton};

/// The egui key at an Onyx key's position (`None` for keys egui has no name for).
pub fn egui_key(key: Key) -> Option<egui::Key> {
    use egui::Key as E;
    Some(match key {
        Key::A => E::A,
        Key::B => E::B,
        Key::C => E::C,
        Key::D => E::D,
        Key::E => E::E,
        Key::F => E::F,
        Key::G => E::G,
        Key::H => E::H,
        Key::I => E::I,
        Key::J => E::J,
        Key::K => E::K,
        Key::L => E::L,
        Key::M => E::M,
        Key::N => E::N,
        Key::O => E::O,
        Key::P => E::P,
        Key::Q => E::Q,
        Key::R => E::R,
        Key::S => E::S,
        Key::T => E::T,
        Key::U => E::U,
        Key::V => E::V,
        Key::W => E::W,
        Key::X => E::X,
        Key::Y => E::Y,
        Key::Z => E::Z,
        Key::Digit0 => E::Num0,
        Key::Digit1 => E::Num1,
        Key::Digit2 => E::Num2,
        Key::Digit3 => E::Num3,
        Key::Digit4 => E::Num4,
        Key::Digit5 => E::Num5,
        Key::Digit6 => E::Num6,
        Key::Digit7 => E::Num7,
        Key::Digit8 => E::Num8,
        Key::Digit9 => E::Num9,
        Key::F1 => E::F1,
        Key::F2 => E::F2,
        Key::F3 => E::F3,
        Key::F4 => E::F4,
        Key::F5 => E::F5,
        Key::F6 => E::F6,
        Key::F7 => E::F7,
        Key::F8 => E::F8,
        Key::F9 => E::F9,
        Key::F10 => E::F10,
        Key::F11 => E::F11,
        Key::F12 => E::F12,
        Key::Escape => E::Escape,
        Key::Enter => E::Enter,
        Key::Space => E::Space,
        Key::Tab => E::Tab,
        Key::Backspace => E::Backspace,
        Key::Delete => E::Delete,
        Key::Insert => E::Insert,
        Key::Home => E::Home,
        Key::End => E::End,
        Key::PageUp => E::PageUp,
        Key::PageDown => E::PageDown,
        Key::ArrowLeft => E::ArrowLeft,
        Key::ArrowRight => E::ArrowRight,
        Key::ArrowUp => E::ArrowUp,
        Key::ArrowDown => E::ArrowDown,
        Key::ShiftLeft => E::ShiftLeft,
        Key::ShiftRight => E::ShiftRight,
        Key::ControlLeft => E::ControlLeft,
        Key::ControlRight => E::ControlRight,
        Key::AltLeft => E::AltLeft,
        Key::AltRight => E::AltRight,
        Key::SuperLeft => E::SuperLeft,
        Key::SuperRight => E::SuperRight,
        Key::Minus => E::Minus,
        Key::Equal => E::Equals,
        Key::BracketLeft => E::OpenBracket,
        Key::BracketRight => E::CloseBracket,
        Key::Backslash => E::Backslash,
        Key::Semicolon => E::Semicolon,
        Key::Quote => E::Quote,
        Key::Backquote => E::Backtick,
        Key::Comma => E::Comma,
        Key::Period => E::Period,
        Key::Slash => E::Slash,
        Key::NumpadEnter => E::Enter,
        Key::NumpadAdd => E::Plus,
        Key::NumpadSubtract => E::Minus,
        Key::NumpadDecimal => E::Period,
        Key::NumpadDivide => E::Slash,
        Key::Numpad0 => E::Num0,
        Key::Numpad1 => E::Num1,
        Key::Numpad2 => E::Num2,
        Key::Numpad3 => E::Num3,
        Key::Numpad4 => E::Num4,
        Key::Numpad5 => E::Num5,
        Key::Numpad6 => E::Num6,
        Key::Numpad7 => E::Num7,
        Key::Numpad8 => E::Num8,
        Key::Numpad9 => E::Num9,
        _ => return None,
    })
}

/// The egui pointer button of a mouse button (`None` for buttons egui does not track).
pub fn egui_button(button: MouseButton) -> Option<egui::PointerButton> {
    Some(match button {
        MouseButton::Left => egui::PointerButton::Primary,
        MouseButton::Right => egui::PointerButton::Secondary,
        MouseButton::Middle => egui::PointerButton::Middle,
        MouseButton::Back => egui::PointerButton::Extra1,
        MouseButton::Forward => egui::PointerButton::Extra2,
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn letters_digits_and_named_keys_map_to_the_same_egui_key() {
        assert_eq!(egui_key(Key::A), Some(egui::Key::A));
        assert_eq!(egui_key(Key::Digit7), Some(egui::Key::Num7));
        assert_eq!(egui_key(Key::Enter), Some(egui::Key::Enter));
        assert_eq!(egui_key(Key::Backquote), Some(egui::Key::Backtick));
        assert_eq!(egui_key(Key::Unknown), None);
    }
}
