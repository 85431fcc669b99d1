//! [`QueryFilter`]: which colliders a scene query may report.

use crate::body_handle::BodyHandle;
use crate::body_type::BodyType;
use crate::collider::Collider;
use crate::collision_groups::CollisionGroups;
use crate::rigid_body::RigidBody;

/// Filter for scene queries. `Default` accepts everything.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct QueryFilter {
    /// Skip colliders of this body (e.g. the caster itself).
    pub exclude_body: Option<BodyHandle>,
    /// Skip static bodies.
    pub exclude_static: bool,
    /// Skip dynamic bodies.
    pub exclude_dynamic: bool,
    /// Only colliders these groups interact with ([`CollisionGroups::interacts_with`]).
    pub groups: Option<CollisionGroups>,
    /// Skip sensors (trigger zones).
    pub exclude_sensors: bool,
}

impl QueryFilter {
    /// True when the collider passes.
    #[must_use]
    pub fn accepts(&self, c: &Collider, body: Option<&RigidBody>) -> bool {
        if self.exclude_body == Some(c.parent)
            || (self.exclude_sensors && c.sensor)
            || self.groups.is_some_and(|g| !g.interacts_with(c.groups))
        {
            return false;
        }
        match body.map(|b| b.body_type) {
            Some(BodyType::Static) => !self.exclude_static,
            Some(BodyType::Dynamic) => !self.exclude_dynamic,
            _ => true,
        }
    }
}
