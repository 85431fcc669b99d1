//! [`DebugLine`] and [`DebugCategories`]: coloured lines drawn over the scene for debugging
//! (colliders, bounds, gizmos), toggled per category.

use glam::Vec3;

/// A set of debug-line categories, as bits. Lines whose category is not enabled in
/// [`crate::RenderSettings::debug_categories`] are skipped.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct DebugCategories(pub u32);

impl DebugCategories {
    /// No category.
    pub const NONE: Self = Self(0);
    /// Physics shapes and contacts.
    pub const PHYSICS: Self = Self(1 << 0);
    /// Bounding volumes.
    pub const BOUNDS: Self = Self(1 << 1);
    /// Editor gizmos and helpers.
    pub const GIZMOS: Self = Self(1 << 2);
    /// Lights and cameras.
    pub const LIGHTS: Self = Self(1 << 3);
    /// Anything the application draws itself.
    pub const USER: Self = Self(1 << 4);
    /// Every category.
    pub const ALL: Self = Self(u32::MAX);

    /// Whether every category of `other` is in `self`.
    #[must_use]
    pub const fn contains(self, other: Self) -> bool {
        self.0 & other.0 == other.0
    }

    /// Whether `self` and `other` share a category.
    #[must_use]
    pub const fn intersects(self, other: Self) -> bool {
        self.0 & other.0 != 0
    }

    /// `self` with `other` added (`on`) or removed.
    #[must_use]
    pub const fn with(self, other: Self, on: bool) -> Self {
        if on {
            Self(self.0 | other.0)
        } else {
            Self(self.0 & !other.0)
        }
    }
}

impl std::ops::BitOr for DebugCategories {
    type Output = Self;
    fn bitor(self, rhs: Self) -> Self {
        Self(self.0 | rhs.0)
    }
}

/// One debug line segment in world space, drawn with a constant width in pixels and no
/// lighting, depth-tested against the scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DebugLine {
    /// Start point, world space, metres.
    pub start: Vec3,
    /// End point, world space, metres.
    pub end: Vec3,
    /// Linear RGBA colour.
    pub color: [f32; 4],
    /// Category (one bit) used to toggle it.
    pub category: DebugCategories,
}

impl DebugLine {
    /// A line of the [`DebugCategories::USER`] category.
    #[must_use]
    pub fn new(start: Vec3, end: Vec3, color: [f32; 4]) -> Self {
        Self {
            start,
            end,
            color,
            category: DebugCategories::USER,
        }
    }

    /// Sets the category.
    #[must_use]
    pub fn with_category(mut self, category: DebugCategories) -> Self {
        self.category = category;
        self
    }
}
