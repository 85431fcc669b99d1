//! The host's state apart from its plugins, in named parts.
//!
//! - `host_state.rs`: [`HostState`]: world, frame I/O, clock, physics, view, tool state.
//! - `frame_io.rs`: [`FrameIo`]: events, input, requests, debug lines of a frame.

mod frame_io;
mod host_state;

pub use frame_io::{FrameIo, DEFAULT_MAX_EVENTS_PER_FRAME};
pub use host_state::HostState;
