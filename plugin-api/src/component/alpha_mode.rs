//! [`AlphaMode`]: how a material's alpha is used.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

/// How a [`Material`](crate::Material)'s alpha (its colour's fourth channel × the texture's)
/// is used, as glTF's `alphaMode`.
#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum AlphaMode {
    /// Alpha ignored: drawn opaque. The default.
    #[default]
    Opaque,
    /// Cut away where alpha is below the material's `alpha_cutoff`, opaque elsewhere (foliage,
    /// fences); casts shadows with the same cut.
    Mask,
    /// Blended over what is behind, drawn after opaque objects, sorted back to front; casts no
    /// shadow.
    Blend,
}
