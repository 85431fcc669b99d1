//! Keyboard and mouse.
//!
//! - `key.rs`: [`Key`], physical keys.
//! - `mouse_button.rs`: [`MouseButton`].
//! - `input_state.rs`: [`InputState`], what is held and what changed this frame.

pub(crate) mod input_state;
mod key;
mod mouse_button;

pub use input_state::InputState;
pub use key::Key;
pub use mouse_button::MouseButton;
