//! [`Collider`]: a shape attached to a body with a local offset and a material.

use glam::Vec3;

use crate::aabb::Aabb;
use crate::body_handle::BodyHandle;
use crate::collision_groups::CollisionGroups;
use crate::material::Material;
use crate::pose::Pose;
use crate::shape::Shape;

/// Broadphase proxy id meaning "not in the tree".
pub(crate) const NO_PROXY: u32 = u32::MAX;

/// A collision shape attached to a body. Create with [`crate::ColliderDesc`] and
/// [`crate::PhysicsWorld::insert_collider`].
#[derive(Clone, Debug)]
pub struct Collider {
    pub(crate) shape: Shape,
    pub(crate) local_pose: Pose,
    pub(crate) parent: BodyHandle,
    pub(crate) material: Material,
    pub(crate) density: f32,
    pub(crate) user_data: u64,
    pub(crate) groups: CollisionGroups,
    pub(crate) sensor: bool,
    pub(crate) proxy: u32,
    pub(crate) aabb: Aabb,
}

impl Collider {
    /// How far a turn of its body by one radian can move the collider's surface, at most,
    /// metres: the reach of its core from the body's centre of mass `local_com` (a ball's
    /// surface does not move as it turns about its own centre). Half spaces: 0.
    pub(crate) fn turning_reach(&self, local_com: Vec3) -> f32 {
        let offset = self.local_pose.translation.distance(local_com);
        offset
            + match self.shape.convex_core() {
                Some((core, _)) => core.reach(),
                None if matches!(self.shape, Shape::HalfSpace(_)) => 0.0,
                None => self.shape.aabb(&Pose::IDENTITY).half_extents().length(),
            }
    }

    /// Whether it is a sensor: it reports overlaps (contact events with
    /// [`crate::ContactEvent::sensor`] set) and pushes nothing.
    #[must_use]
    pub fn is_sensor(&self) -> bool {
        self.sensor
    }

    /// Its collision groups.
    #[must_use]
    pub fn collision_groups(&self) -> CollisionGroups {
        self.groups
    }

    /// The shape.
    #[must_use]
    pub fn shape(&self) -> &Shape {
        &self.shape
    }

    /// Pose relative to the parent body origin.
    #[must_use]
    pub fn local_pose(&self) -> Pose {
        self.local_pose
    }

    /// Owning body.
    #[must_use]
    pub fn parent(&self) -> BodyHandle {
        self.parent
    }

    /// Surface material.
    #[must_use]
    pub fn material(&self) -> &Material {
        &self.material
    }

    /// Sets the material (takes effect at the next step).
    pub fn set_material(&mut self, m: Material) {
        self.material = m;
    }

    /// Density in kg/m³ used for the body's mass.
    #[must_use]
    pub fn density(&self) -> f32 {
        self.density
    }

    /// World bounds as of the last step (not enlarged).
    #[must_use]
    pub fn aabb(&self) -> Aabb {
        self.aabb
    }

    /// User payload.
    #[must_use]
    pub fn user_data(&self) -> u64 {
        self.user_data
    }
}
