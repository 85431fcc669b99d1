//! [`QueryFilter`]: which colliders a query sees.

use crate::Entity;

/// Which colliders an overlap query or a shape cast sees
/// ([`Ctx::overlap`](crate::Ctx::overlap), [`Ctx::shape_cast`](crate::Ctx::shape_cast)).
/// `Default` sees every collider, sensors included.
///
/// ```
/// # use onyx_plugin_api::{Entity, QueryFilter};
/// # let player = Entity::from_bits(1);
/// // Solid things in group 1 other than the player's own colliders:
/// let filter = QueryFilter::default().excluding(player).without_sensors().with_groups(u32::MAX, 1);
/// # let _ = filter;
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct QueryFilter {
    /// The groups the query counts as a member of (bits of 32; default all). A collider
    /// whose `filter` leaves all of these out does not see it.
    pub memberships: u32,
    /// The groups the query sees (default all): a collider is seen when its `memberships`
    /// meet this and its `filter` meets the query's `memberships`, as two colliders decide
    /// whether they collide.
    pub filter: u32,
    /// Leave out this entity's body: its own collider and every collider of its compound
    /// (the caster itself). A collider-only child names its body's entity here too.
    pub exclude: Option<Entity>,
    /// Whether sensors (trigger zones) are seen (default `true`).
    pub sensors: bool,
}

impl Default for QueryFilter {
    fn default() -> Self {
        Self {
            memberships: u32::MAX,
            filter: u32::MAX,
            exclude: None,
            sensors: true,
        }
    }
}

impl QueryFilter {
    /// Returns this filter leaving out `entity`'s body.
    #[must_use]
    pub const fn excluding(mut self, entity: Entity) -> Self {
        self.exclude = Some(entity);
        self
    }

    /// Returns this filter as a member of `memberships`, seeing `filter`.
    #[must_use]
    pub const fn with_groups(mut self, memberships: u32, filter: u32) -> Self {
        self.memberships = memberships;
        self.filter = filter;
        self
    }

    /// Returns this filter seeing no sensors.
    #[must_use]
    pub const fn without_sensors(mut self) -> Self {
        self.sensors = false;
        self
    }
}
