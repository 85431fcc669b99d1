//! What plugins ask of the physics world besides forces and rays: overlap queries, shape
//! casts, a joint's coordinate and moving kinematic characters (`Ctx::overlap`,
//! `Ctx::shape_cast`, `Ctx::joint_coordinate`, `Ctx::move_character`).

use onyx_physics::glam::{Affine3A, Vec3};
use onyx_physics::shape::{Capsule, Cuboid, Shape, Sphere};
use onyx_physics::{BodyType, CollisionGroups, Pose, QueryFilter, ShapeHit};
use onyx_plugin_api::{
    CharacterController, CharacterMove, ColliderShape, Entity, RayHit, Transform,
};

use super::physics_system::rigid;
use super::PhysicsSystem;
use crate::entity_id::{to_api, to_hecs};
use crate::world::WorldState;

/// Why a physics request could not be served, as a sentence.
pub type QueryError = String;

impl PhysicsSystem {
    /// The engine's filter for a plugin's.
    fn engine_filter(&self, filter: &onyx_plugin_api::QueryFilter) -> QueryFilter {
        QueryFilter {
            exclude_body: filter
                .exclude
                .and_then(to_hecs)
                .and_then(|e| self.body_of(e)),
            groups: Some(CollisionGroups::new(filter.memberships, filter.filter)),
            exclude_sensors: !filter.sensors,
            ..QueryFilter::default()
        }
    }

    /// A query's shape placed and scaled at `pose`.
    fn query_shape(shape: ColliderShape, pose: &Transform) -> Result<(Shape, Pose), QueryError> {
        let positive = |v: f32| v.is_finite() && v > 0.0;
        let shape = match shape {
            ColliderShape::Sphere { radius } if positive(radius) => {
                Shape::Sphere(Sphere { radius })
            }
            ColliderShape::Box { half_extents } if half_extents.iter().all(|&h| positive(h)) => {
                Shape::Cuboid(Cuboid {
                    half_extents: Vec3::from(half_extents),
                })
            }
            ColliderShape::Capsule {
                half_height,
                radius,
            } if half_height.is_finite() && half_height >= 0.0 && positive(radius) => {
                Shape::Capsule(Capsule {
                    half_height,
                    radius,
                })
            }
            ColliderShape::Sphere { .. }
            | ColliderShape::Box { .. }
            | ColliderShape::Capsule { .. } => {
                return Err(format!(
                    "a query shape needs finite sizes above zero, got {shape:?}"
                ))
            }
            ColliderShape::Plane
            | ColliderShape::ConvexHull { .. }
            | ColliderShape::TriMesh { .. } => {
                return Err(format!(
                    "queries take a sphere, a box or a capsule, not {shape:?}"
                ))
            }
        };
        if !pose.is_finite() {
            return Err("the query's pose holds NaN or infinity".into());
        }
        let scaled = shape.scaled(pose.scale)?.shape;
        Ok((
            scaled,
            Pose::new(pose.translation, pose.rotation.normalize()),
        ))
    }

    /// The entities whose colliders overlap `shape` at `pose`, each once.
    pub fn overlap(
        &self,
        shape: ColliderShape,
        pose: &Transform,
        filter: &onyx_plugin_api::QueryFilter,
    ) -> Result<Vec<Entity>, QueryError> {
        let (shape, pose) = Self::query_shape(shape, pose)?;
        let mut out: Vec<Entity> = Vec::new();
        for collider in self
            .world
            .intersect_shape(&shape, &pose, &self.engine_filter(filter))
        {
            if let Some(e) = self.collider_entity.get(&collider) {
                let e = to_api(*e);
                if !out.contains(&e) {
                    out.push(e);
                }
            }
        }
        Ok(out)
    }

    /// The first collider `shape` meets swept from `pose` along `direction`.
    pub fn shape_cast(
        &self,
        shape: ColliderShape,
        pose: &Transform,
        direction: Vec3,
        max_distance: f32,
        filter: &onyx_plugin_api::QueryFilter,
    ) -> Result<Option<RayHit>, QueryError> {
        let (shape, pose) = Self::query_shape(shape, pose)?;
        if !(direction.is_finite() && max_distance.is_finite() && max_distance >= 0.0) {
            return Err(format!(
                "a shape cast needs a finite direction and distance, got {direction} and {max_distance}"
            ));
        }
        let hit = self.world.cast_shape(
            &shape,
            &pose,
            direction,
            max_distance,
            0.0,
            &self.engine_filter(filter),
        );
        Ok(hit.and_then(|h| self.ray_hit(&h)))
    }

    fn ray_hit(&self, hit: &ShapeHit) -> Option<RayHit> {
        let entity = self.collider_entity.get(&hit.collider)?;
        Some(RayHit {
            entity: to_api(*entity),
            point: hit.point,
            normal: hit.normal,
            distance: hit.distance,
        })
    }

    /// The coordinate of the joint made from the `Joint` component of `e`.
    pub fn joint_coordinate(&self, e: hecs::Entity) -> Option<f32> {
        self.world.joint_coordinate(self.joints.handle(e)?)
    }

    /// Moves the kinematic character `entity` by `desired` as far as the world lets it and
    /// writes its new world pose into its transform (its body follows in the next step).
    pub fn move_character(
        &mut self,
        world: &mut WorldState,
        entity: Entity,
        desired: Vec3,
        controller: &CharacterController,
    ) -> Result<CharacterMove, QueryError> {
        if !desired.is_finite() {
            return Err(format!(
                "move_character: the desired move {desired} is not finite"
            ));
        }
        let e = to_hecs(entity).ok_or_else(|| format!("entity {entity} does not exist"))?;
        let Some(body) = self.own_body(e) else {
            return Err(format!(
                "entity {entity} has no physics body yet: a character needs a kinematic \
                 RigidBody and a collider (bodies are made at the next fixed step)"
            ));
        };
        let kind = self
            .world
            .body(body)
            .map(onyx_physics::RigidBody::body_type);
        if kind != Some(BodyType::Kinematic) {
            return Err(format!(
                "entity {entity} is not a kinematic body: move_character moves kinematic \
                 characters (RigidBody::kinematic())"
            ));
        }
        let world_pose: Affine3A = world.world_pose(e);
        let start = rigid(&world_pose);
        let engine = onyx_physics::CharacterController {
            offset: controller.offset.max(0.0),
            max_slope_climb_angle: controller.max_slope_climb_angle,
            step_height: controller.step_height.max(0.0),
            snap_to_ground: controller.snap_to_ground.max(0.0),
            push_dynamic_bodies: controller.push_dynamic_bodies,
        };
        let moved = self
            .world
            .move_character(body, &start, desired, &engine)
            .ok_or_else(|| {
                format!("entity {entity} has no solid convex collider to move as a character")
            })?;
        let (scale, rotation, translation) = world_pose.to_scale_rotation_translation();
        let to = Transform {
            translation: translation + moved.translation,
            rotation,
            scale,
        };
        world
            .set_world_pose(e, &to)
            .map_err(|_| format!("entity {entity} is under a parent scaled to zero"))?;
        Ok(CharacterMove {
            translation: moved.translation,
            grounded: moved.grounded,
            collisions: moved
                .collisions
                .iter()
                .filter_map(|h| self.ray_hit(h))
                .collect(),
        })
    }
}

#[cfg(test)]
mod tests {
    /// The plugin-side controller's defaults are the engine's (the docs of both say them).
    #[test]
    fn the_character_controller_defaults_are_the_engines() {
        let api = onyx_plugin_api::CharacterController::default();
        let engine = onyx_physics::CharacterController::default();
        assert_eq!(api.offset, engine.offset);
        assert_eq!(api.max_slope_climb_angle, engine.max_slope_climb_angle);
        assert_eq!(api.step_height, engine.step_height);
        assert_eq!(api.snap_to_ground, engine.snap_to_ground);
        assert_eq!(api.push_dynamic_bodies, engine.push_dynamic_bodies);
    }
}
