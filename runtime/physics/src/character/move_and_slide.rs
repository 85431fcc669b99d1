//! The move of a kinematic character: slide along what it meets, climb steps, snap to the
//! ground. Shape casts only ([`PhysicsWorld::cast_shape`]); the world is not changed here.

use glam::Vec3;

use super::character_controller::{CharacterController, CHARACTER_MAX_SLIDES};
use super::character_move::CharacterMove;
use crate::body_handle::BodyHandle;
use crate::body_type::BodyType;
use crate::physics_world::PhysicsWorld;
use crate::pose::Pose;
use crate::query::{QueryFilter, ShapeHit};
use crate::shape::Shape;

/// Movements shorter than this are no movement, metres.
const MIN_MOVE: f32 = 1e-5;

/// How far past an edge contact, and above it, the ray that finds the face under it starts,
/// metres (see `Mover::stands_on`).
const EDGE_PROBE: f32 = 5e-3;

impl PhysicsWorld {
    /// Moves the character whose body is `body`, standing at `start`, by `desired` (world
    /// axes, metres: its velocity times one step, gravity included) as far as the world
    /// lets it: sliding along walls and slopes steeper than the largest it climbs, walking
    /// up gentler ones, climbing steps up to the step height, staying on the ground going
    /// down (snap), and pushing the dynamic bodies it runs into (see
    /// [`CharacterController`]). The character's shape is the body's first solid convex
    /// collider; its own body and sensors are not in its way.
    ///
    /// The body is not moved: add [`CharacterMove::translation`] to its pose (a kinematic
    /// body's next pose, so it carries what it pushes). `None` when the body is not there
    /// or has no convex solid collider.
    pub fn move_character(
        &mut self,
        body: BodyHandle,
        start: &Pose,
        desired: Vec3,
        controller: &CharacterController,
    ) -> Option<CharacterMove> {
        if !(desired.is_finite() && start.translation.is_finite()) {
            return None;
        }
        let b = self.bodies.get(body)?;
        let collider = b.colliders.iter().find_map(|&h| {
            let c = self.colliders.get(h)?;
            (!c.sensor && c.shape.convex_core().is_some()).then_some(c)
        })?;
        let shape_pose = start.mul_pose(&collider.local_pose);
        let mover = Mover {
            world: self,
            shape: &collider.shape,
            rotation: shape_pose.rotation,
            filter: QueryFilter {
                exclude_body: Some(body),
                exclude_sensors: true,
                groups: Some(collider.groups),
                ..QueryFilter::default()
            },
            controller,
        };
        let moved = mover.plan(shape_pose.translation, desired);
        if controller.push_dynamic_bodies && self.settings.dt > 0.0 {
            self.push_bodies(&moved, desired / self.settings.dt);
        }
        Some(moved)
    }
}

/// One character's move: its shape, the filter that leaves its own body out, its settings.
pub(super) struct Mover<'a> {
    pub world: &'a PhysicsWorld,
    pub shape: &'a Shape,
    pub rotation: glam::Quat,
    pub filter: QueryFilter,
    pub controller: &'a CharacterController,
}

impl Mover<'_> {
    fn cast(&self, at: Vec3, dir: Vec3, distance: f32) -> Option<ShapeHit> {
        self.world.cast_shape(
            self.shape,
            &Pose::new(at, self.rotation),
            dir,
            distance,
            self.controller.offset,
            &self.filter,
        )
    }

    /// The walkable ground within `distance` below the shape at `at`, if any.
    fn ground(&self, at: Vec3, distance: f32) -> Option<ShapeHit> {
        self.cast(at, Vec3::NEG_Y, distance)
            .filter(|hit| self.stands_on(hit, at))
    }

    /// Whether the shape at `at` can stand where `hit` touches: the contact's normal is
    /// walkable, or — at an edge or corner, where a rounded shape's contact normal leans
    /// over — the face a short ray finds straight down just past the point (away from the
    /// shape's axis) is.
    fn stands_on(&self, hit: &ShapeHit, at: Vec3) -> bool {
        if self.controller.walkable(hit.normal) {
            return true;
        }
        let away = Vec3::new(hit.point.x - at.x, 0.0, hit.point.z - at.z).normalize_or_zero();
        let origin = hit.point + away * EDGE_PROBE + Vec3::Y * EDGE_PROBE;
        self.world
            .cast_ray(origin, Vec3::NEG_Y, 2.0 * EDGE_PROBE, &self.filter)
            .is_some_and(|ray| self.controller.walkable(ray.normal))
    }

    /// The whole move of the shape from `start` by `desired`.
    pub fn plan(&self, start: Vec3, desired: Vec3) -> CharacterMove {
        let c = self.controller;
        let probe = 2.0 * c.offset + MIN_MOVE;
        let grounded_before = self.ground(start, probe).is_some();
        let mut at = start;
        let mut remaining = desired;
        let mut collisions = Vec::new();
        for _ in 0..CHARACTER_MAX_SLIDES {
            let length = remaining.length();
            if length <= MIN_MOVE {
                break;
            }
            let dir = remaining / length;
            let Some(hit) = self.cast(at, dir, length) else {
                at += remaining;
                break;
            };
            at += dir * hit.distance;
            remaining -= dir * hit.distance;
            collisions.push(hit);
            let n = hit.normal;
            if !c.walkable(n) && grounded_before && !self.is_dynamic(hit.body) {
                if let Some((stepped, left)) = self.step_up(at, remaining) {
                    at = stepped;
                    remaining = left;
                    continue;
                }
            }
            remaining -= n * remaining.dot(n).min(0.0);
            if !c.walkable(n) && remaining.y > 0.0 && desired.y <= 0.0 {
                // A wall or a slope too steep: sliding must not carry the character up it.
                remaining.y = 0.0;
                let across = Vec3::new(n.x, 0.0, n.z).normalize_or_zero();
                remaining -= across * remaining.dot(across).min(0.0);
            }
        }
        let mut grounded = self.ground(at, probe).is_some();
        if !grounded && grounded_before && desired.y <= 0.0 && c.snap_to_ground > 0.0 {
            if let Some(hit) = self.ground(at, c.snap_to_ground) {
                at.y -= hit.distance;
                grounded = true;
            }
        }
        CharacterMove {
            translation: at - start,
            grounded,
            collisions,
        }
    }

    fn is_dynamic(&self, body: BodyHandle) -> bool {
        self.world
            .body(body)
            .is_some_and(|b| b.body_type() == BodyType::Dynamic)
    }

    /// Climbs onto a step in the way: up by at most the step height, forward by what is left
    /// of the horizontal move, down onto a walkable top. Returns where it ends and what is
    /// left of the move, or `None` when there is no step to stand on within reach.
    fn step_up(&self, at: Vec3, remaining: Vec3) -> Option<(Vec3, Vec3)> {
        let c = self.controller;
        let horizontal = Vec3::new(remaining.x, 0.0, remaining.z);
        let length = horizontal.length();
        if c.step_height <= 0.0 || length <= MIN_MOVE {
            return None;
        }
        let dir = horizontal / length;
        let up = self
            .cast(at, Vec3::Y, c.step_height)
            .map_or(c.step_height, |h| h.distance);
        let raised = at + Vec3::Y * up;
        let forward = self
            .cast(raised, dir, length)
            .map_or(length, |h| h.distance);
        if forward <= MIN_MOVE {
            return None; // higher than a step: a wall at the raised height too
        }
        let over = raised + dir * forward;
        let top = self.ground(over, up + c.offset)?;
        // The step's top, measured from the shape's lowest point before the climb.
        let foot = at.y + self.shape.aabb(&Pose::new(Vec3::ZERO, self.rotation)).min.y;
        if top.point.y - foot > c.step_height + c.offset {
            return None; // an edge higher than a step, rolled onto from above
        }
        let landed = over - Vec3::Y * top.distance;
        if landed.y - at.y <= MIN_MOVE {
            return None; // nothing was climbed: not a step
        }
        Some((
            landed,
            horizontal - dir * forward + Vec3::Y * remaining.y.min(0.0),
        ))
    }
}
