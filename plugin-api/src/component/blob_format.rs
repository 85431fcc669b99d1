//! [`BlobFormat`]: how the bytes of a plugin component are encoded.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

/// Encoding of a plugin component's bytes in the host's world.
#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum BlobFormat {
    /// JSON written by serde ([`Component`](crate::Component)): the host can decode it
    /// for scene files and state dumps.
    Json,
    /// Opaque bytes ([`Ctx::set_raw`](crate::Ctx::set_raw)): stored and shown as base64.
    Raw,
}
