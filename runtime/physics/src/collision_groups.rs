//! [`CollisionGroups`]: which of 32 groups a collider is in, and which it collides with.

/// Membership and filter bitmasks (32 groups). Two colliders collide only when each one's
/// memberships meet the other's filter: `(a.memberships & b.filter) != 0 &&
/// (b.memberships & a.filter) != 0` (rapier's rule), so either side can refuse.
///
/// ```
/// use onyx_physics::CollisionGroups;
/// const PLAYER: u32 = 1 << 0;
/// const BULLETS: u32 = 1 << 1;
/// // Bullets collide with everything but the player (and each other).
/// let bullet = CollisionGroups::new(BULLETS, !(PLAYER | BULLETS));
/// let player = CollisionGroups::new(PLAYER, u32::MAX);
/// assert!(!bullet.interacts_with(player));
/// assert!(bullet.interacts_with(CollisionGroups::ALL));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CollisionGroups {
    /// The groups this collider is in.
    pub memberships: u32,
    /// The groups it collides with.
    pub filter: u32,
}

impl CollisionGroups {
    /// In every group, colliding with every group (the default).
    pub const ALL: Self = Self {
        memberships: u32::MAX,
        filter: u32::MAX,
    };

    /// In `memberships`, colliding with `filter`.
    #[must_use]
    pub const fn new(memberships: u32, filter: u32) -> Self {
        Self {
            memberships,
            filter,
        }
    }

    /// Whether colliders with these groups and `other` collide.
    #[must_use]
    pub const fn interacts_with(self, other: Self) -> bool {
        self.memberships & other.filter != 0 && other.memberships & self.filter != 0
    }
}

impl Default for CollisionGroups {
    fn default() -> Self {
        Self::ALL
    }
}
