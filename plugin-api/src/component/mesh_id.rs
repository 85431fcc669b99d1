//! [`MeshId`] and [`TextureId`]: handles to meshes and textures held by the host.

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

/// A mesh the host can draw: a built-in shape, or a model loaded with
/// [`Ctx::load_mesh`](crate::Ctx::load_mesh). Valid for the life of the host.
#[repr(transparent)]
#[derive(
    StableAbi, Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize,
)]
#[serde(transparent)]
pub struct MeshId(pub u32);

impl MeshId {
    /// A unit cube (1 m sides) centred on the origin.
    pub const CUBE: Self = Self(1);
    /// A sphere of radius 0.5 m.
    pub const SPHERE: Self = Self(2);
    /// A 1 m × 1 m plane on XZ, facing +Y.
    pub const PLANE: Self = Self(3);
    /// A capsule of radius 0.5 m and total height 2 m along Y.
    pub const CAPSULE: Self = Self(4);
    /// A cylinder of radius 0.5 m and height 1 m along Y.
    pub const CYLINDER: Self = Self(5);
    /// The built-in shapes with their scene-file names.
    pub const BUILTIN: [(Self, &'static str); 5] = [
        (Self::CUBE, "cube"),
        (Self::SPHERE, "sphere"),
        (Self::PLANE, "plane"),
        (Self::CAPSULE, "capsule"),
        (Self::CYLINDER, "cylinder"),
    ];
    /// First id given to loaded models.
    pub const FIRST_LOADED: u32 = 16;
}

/// A texture loaded with [`Ctx::load_texture`](crate::Ctx::load_texture), or none.
#[repr(transparent)]
#[derive(
    StableAbi,
    Clone,
    Copy,
    Debug,
    Default,
    PartialEq,
    Eq,
    Hash,
    PartialOrd,
    Ord,
    Serialize,
    Deserialize,
)]
#[serde(transparent)]
pub struct TextureId(pub u32);

impl TextureId {
    /// No texture (the model's own, if it has one).
    pub const NONE: Self = Self(0);
}
