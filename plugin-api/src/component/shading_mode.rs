//! [`ShadingMode`]: how an object is drawn.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

/// How an object is shaded; chosen per entity in its [`Material`](crate::Material).
#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ShadingMode {
    /// Flat colour, no lighting.
    Unlit,
    /// Lit, untextured.
    LitLow,
    /// Lit, colour × albedo texture (the model's own texture when none is set). The default.
    #[default]
    Lit,
    /// World-space normals as colour.
    Normal,
    /// Triangle edges in the material colour.
    Wireframe,
}
