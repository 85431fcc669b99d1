//! [`LockedAxes`]: per-axis translation and rotation locks.

/// Bit set of locked world axes. A locked translation axis keeps its linear velocity at zero;
/// a locked rotation axis keeps its angular velocity component at zero and ignores contact torque.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct LockedAxes(pub u8);

impl LockedAxes {
    /// Nothing locked.
    pub const NONE: Self = Self(0);
    /// Lock translation along X.
    pub const TRANSLATION_X: Self = Self(1);
    /// Lock translation along Y.
    pub const TRANSLATION_Y: Self = Self(2);
    /// Lock translation along Z.
    pub const TRANSLATION_Z: Self = Self(4);
    /// Lock rotation about X.
    pub const ROTATION_X: Self = Self(8);
    /// Lock rotation about Y.
    pub const ROTATION_Y: Self = Self(16);
    /// Lock rotation about Z.
    pub const ROTATION_Z: Self = Self(32);
    /// All translations.
    pub const ALL_TRANSLATIONS: Self = Self(7);
    /// All rotations.
    pub const ALL_ROTATIONS: Self = Self(56);

    /// True when every bit of `other` is set.
    #[inline]
    #[must_use]
    pub fn contains(self, other: Self) -> bool {
        self.0 & other.0 == other.0
    }

    /// Union of both sets.
    #[inline]
    #[must_use]
    pub fn union(self, other: Self) -> Self {
        Self(self.0 | other.0)
    }

    /// Multiplier per axis: 0 where translation is locked, 1 elsewhere.
    #[inline]
    #[must_use]
    pub fn translation_mask(self) -> glam::Vec3 {
        glam::Vec3::new(
            f32::from(u8::from(self.0 & 1 == 0)),
            f32::from(u8::from(self.0 & 2 == 0)),
            f32::from(u8::from(self.0 & 4 == 0)),
        )
    }

    /// Multiplier per axis: 0 where rotation is locked, 1 elsewhere.
    #[inline]
    #[must_use]
    pub fn rotation_mask(self) -> glam::Vec3 {
        glam::Vec3::new(
            f32::from(u8::from(self.0 & 8 == 0)),
            f32::from(u8::from(self.0 & 16 == 0)),
            f32::from(u8::from(self.0 & 32 == 0)),
        )
    }
}

impl std::ops::BitOr for LockedAxes {
    type Output = Self;
    fn bitor(self, rhs: Self) -> Self {
        self.union(rhs)
    }
}
