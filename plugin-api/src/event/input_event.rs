//! [`InputEvent`]: events whose source is the keyboard or the mouse.

use crate::{Key, MouseButton};

/// A keyboard or mouse event. The same changes are folded into
/// [`InputState`](crate::InputState) for plugins that poll instead.
#[derive(Clone, Debug, PartialEq)]
pub enum InputEvent {
    /// A key went down (`pressed`) or up; `repeat` marks auto-repeat while held.
    Key {
        /// Which key.
        key: Key,
        /// Down (`true`) or up (`false`).
        pressed: bool,
        /// Whether this is an auto-repeat of a held key.
        repeat: bool,
    },
    /// A mouse button went down or up.
    MouseButton {
        /// Which button.
        button: MouseButton,
        /// Down (`true`) or up (`false`).
        pressed: bool,
    },
    /// The cursor moved to (x, y) physical pixels from the window's top-left corner.
    CursorMoved {
        /// Horizontal position, pixels.
        x: f32,
        /// Vertical position, pixels (down is positive).
        y: f32,
    },
    /// Raw mouse motion, not limited by the window edge (for camera control).
    MouseMotion {
        /// Horizontal motion.
        dx: f32,
        /// Vertical motion.
        dy: f32,
    },
    /// The wheel or touchpad scrolled, in lines.
    Scroll {
        /// Horizontal scroll.
        dx: f32,
        /// Vertical scroll (positive is up / away from the user).
        dy: f32,
    },
    /// Text typed (after keyboard layout and IME), for text fields.
    Text(String),
}
