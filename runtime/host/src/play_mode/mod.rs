//! Play mode for the editor: Edit (no fixed steps, no scripts) → Play (world snapshot
//! taken) → Pause / Step → Stop (world put back as it was at Play).
//!
//! - `play_session.rs`: [`PlaySession`], the mode and the commands waiting to be applied.
//! - `world_snapshot.rs`: [`WorldSnapshot`], a copy of every entity with its handle.

mod play_session;
mod world_snapshot;

pub use play_session::PlaySession;
pub use world_snapshot::WorldSnapshot;
