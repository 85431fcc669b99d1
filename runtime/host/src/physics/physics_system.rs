//! [`PhysicsSystem`]: onyx-physics driven by `RigidBody` and `Collider` components.

use std::collections::{HashMap, HashSet};

use onyx_physics::glam::{Affine3A, Quat, Vec3};
use onyx_physics::{
    BodyHandle, BodyType, ColliderDesc, ColliderHandle, CollisionGroups, ContactEventKind,
    MassProperties, PhysicsSettings, PhysicsWorld, Pose, QueryFilter, RigidBodyDesc,
};
use onyx_plugin_api::host::PhysicsCommand;
use onyx_plugin_api::{
    BodyKind, Collider, ColliderShape, Entity, Event, GraphicsEvent, Joint, Name, PhysicsEvent,
    PlatformEvent, RayHit, RigidBody, Transform,
};

use super::compound::{self, PlacedCollider, Placement};
use super::joint_links::JointLinks;
use super::step_reports::{Named, StepReports};
use super::ScenePhysics;
use crate::assets::AssetRegistry;
use crate::entity_id::{to_api, to_hecs};
use crate::entity_map::EntityMap;
use crate::hierarchy::world_pose;
use crate::world::WorldState;

/// What the host keeps per simulated body (keyed by the entity that owns it: the one with
/// the `RigidBody`, or a static collider's own entity).
#[derive(Clone, Debug)]
struct Link {
    body: BodyHandle,
    /// The `RigidBody` configuration the body was built from: a change rebuilds it.
    rigid_body: Option<RigidBody>,
    /// The colliders on the body as they were built: a change replaces them (the body keeps
    /// its motion).
    colliders: Vec<(PlacedCollider, ColliderHandle)>,
    /// The local transform and velocities written back after the last step (or seen at the
    /// last sync): a difference means the user moved the entity.
    written: Transform,
    /// The world pose the body had after the last step: a difference means the entity moved
    /// with its parents.
    written_pose: Pose,
    written_velocity: (Vec3, Vec3),
    /// A parent moved a dynamic body's entity: its local transform must be written back even
    /// while the body sleeps.
    parent_moved: bool,
    /// The last write-back was of a sleeping or static body: until it wakes or moves there
    /// is nothing new to write.
    settled: bool,
    /// The [`PhysicsSystem::sync`] that last found the entity with its components.
    seen: u64,
}

impl Link {
    /// Whether the body carries exactly these colliders, placed as they are now.
    fn carries(&self, colliders: &[PlacedCollider]) -> bool {
        self.colliders.len() == colliders.len()
            && self
                .colliders
                .iter()
                .zip(colliders)
                .all(|((built, _), now)| built == now)
    }
}

/// The physics world behind the components. Empty scenes cost nothing: with no collider in
/// the world, a step does no work.
pub struct PhysicsSystem {
    pub(super) world: PhysicsWorld,
    links: EntityMap<Link>,
    entity_of: HashMap<BodyHandle, hecs::Entity>,
    /// The entity holding each collider's component (events and queries name it).
    pub(super) collider_entity: HashMap<ColliderHandle, hecs::Entity>,
    /// Colliders removed since the last step, whose "contact ended" events arrive with it.
    departed: HashMap<ColliderHandle, hecs::Entity>,
    /// Colliders that could not be built, kept so each failure is reported once (until the
    /// component or its placement changes).
    failed: HashMap<hecs::Entity, (Collider, Placement)>,
    /// Entities already warned that their non-uniform scale made a sphere or capsule round.
    warned_scale: HashSet<hecs::Entity>,
    commands: Vec<(Entity, PhysicsCommand)>,
    /// The preset and overrides chosen by a scene file or the host, if any.
    scene_physics: Option<ScenePhysics>,
    /// Counts syncs; a link not stamped with the current one has lost its entity.
    sync_epoch: u64,
    /// What the steps reported that was already logged.
    reports: StepReports,
    /// The physics joints of `Joint` components.
    pub(super) joints: JointLinks,
}

impl std::fmt::Debug for PhysicsSystem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PhysicsSystem")
            .field("bodies", &self.links.len())
            .finish()
    }
}

impl Default for PhysicsSystem {
    fn default() -> Self {
        Self::new(PhysicsSettings::default())
    }
}

/// The rigid part (translation and rotation) of a world pose: bodies have no scale.
pub(super) fn rigid(pose: &Affine3A) -> Pose {
    let (_, rotation, translation) = pose.to_scale_rotation_translation();
    Pose {
        translation,
        rotation: rotation.normalize(),
    }
}

/// The world pose of the entity of transform `t` as physics takes it.
fn body_pose(world: &WorldState, e: hecs::Entity, t: &Transform) -> Pose {
    match world.hierarchy.cached_world(e) {
        Some(pose) => rigid(&pose),
        None => Pose {
            translation: t.translation,
            rotation: t.rotation,
        },
    }
}

fn body_desc(rb: Option<&RigidBody>, pose: &Pose) -> RigidBodyDesc {
    let pose_desc = |d: RigidBodyDesc| d.translation(pose.translation).rotation(pose.rotation);
    let Some(rb) = rb else {
        return pose_desc(RigidBodyDesc::fixed());
    };
    let desc = match rb.kind {
        BodyKind::Dynamic => RigidBodyDesc::dynamic(),
        BodyKind::Kinematic => RigidBodyDesc::kinematic(),
        BodyKind::Static => RigidBodyDesc::fixed(),
    };
    pose_desc(desc)
        .linvel(rb.linear_velocity)
        .angvel(rb.angular_velocity)
        .gravity_scale(rb.gravity_scale)
        .linear_damping(rb.linear_damping)
        .angular_damping(rb.angular_damping)
        .locked_axes(onyx_physics::LockedAxes(rb.locked_axes.0))
        .ccd_enabled(rb.ccd)
        .can_sleep(rb.can_sleep)
}

impl PhysicsSystem {
    /// A physics system with `settings` (the host sets `dt` to its fixed step).
    pub fn new(settings: PhysicsSettings) -> Self {
        Self {
            world: PhysicsWorld::new(settings),
            links: EntityMap::default(),
            entity_of: HashMap::new(),
            collider_entity: HashMap::new(),
            departed: HashMap::new(),
            failed: HashMap::new(),
            warned_scale: HashSet::new(),
            commands: Vec::new(),
            scene_physics: None,
            sync_epoch: 0,
            reports: StepReports::default(),
            joints: JointLinks::default(),
        }
    }

    /// The physics world (read-only: the components drive it).
    pub fn world(&self) -> &PhysicsWorld {
        &self.world
    }

    /// Uses a scene's preset and overrides (the step length still follows the host's fixed
    /// step).
    pub fn set_scene_physics(&mut self, physics: ScenePhysics) {
        let dt = self.world.settings().dt;
        *self.world.settings_mut() = PhysicsSettings {
            dt,
            ..physics.settings()
        };
        self.scene_physics = Some(physics);
    }

    /// The preset and overrides set with [`PhysicsSystem::set_scene_physics`].
    pub fn scene_physics(&self) -> Option<&ScenePhysics> {
        self.scene_physics.as_ref()
    }

    /// The settings, to tune accuracy and cost.
    pub fn settings_mut(&mut self) -> &mut PhysicsSettings {
        self.world.settings_mut()
    }

    /// Queues a force, torque, impulse or velocity for `entity`'s body, applied before the
    /// next step. Fails if the entity has no body.
    pub fn command(&mut self, entity: Entity, command: PhysicsCommand) -> Result<(), String> {
        let finite = match command {
            PhysicsCommand::Force(v) | PhysicsCommand::Torque(v) | PhysicsCommand::Impulse(v) => {
                v.iter().all(|x| x.is_finite())
            }
            PhysicsCommand::Velocity { linear, angular } => {
                linear.iter().chain(&angular).all(|x| x.is_finite())
            }
        };
        if !finite {
            return Err("a force, torque, impulse or velocity holds NaN or infinity".into());
        }
        self.commands.push((entity, command));
        Ok(())
    }

    /// The body of `e`: its own (a `RigidBody`'s, or a static collider's), or the body its
    /// collider belongs to.
    pub(super) fn body_of(&self, e: hecs::Entity) -> Option<BodyHandle> {
        if let Some(link) = self.links.get(e) {
            return Some(link.body);
        }
        let (&collider, _) = self.collider_entity.iter().find(|(_, &x)| x == e)?;
        self.world
            .collider(collider)
            .map(onyx_physics::Collider::parent)
    }

    /// The body `e` owns (it holds the `RigidBody`, or is a static collider of its own).
    pub(super) fn own_body(&self, e: hecs::Entity) -> Option<BodyHandle> {
        self.links.get(e).map(|link| link.body)
    }

    /// The first collider along a ray.
    pub fn raycast(&self, origin: Vec3, direction: Vec3, max_distance: f32) -> Option<RayHit> {
        let length = direction.length();
        if !(length.is_finite() && length > 0.0 && origin.is_finite() && max_distance >= 0.0) {
            return None;
        }
        let hit = self.world.cast_ray(
            origin,
            direction / length,
            max_distance,
            &QueryFilter::default(),
        )?;
        let entity = self.collider_entity.get(&hit.collider)?;
        Some(RayHit {
            entity: to_api(*entity),
            point: hit.point,
            normal: hit.normal,
            distance: hit.toi,
        })
    }

    /// Debug outlines of colliders, contact points and normals.
    pub fn debug_lines(&self) -> Vec<onyx_plugin_api::DebugLine> {
        self.world
            .debug_lines()
            .into_iter()
            .map(|l| onyx_plugin_api::DebugLine::new(l.a, l.b, l.color))
            .collect()
    }

    /// One fixed step of `dt` seconds: components → bodies, queued commands, the step, then
    /// poses and state back into the components and contacts into `events`.
    ///
    /// Bodies live in world space: each is built at its entity's world pose (the scene
    /// graph's, brought up to date before the step). A static or kinematic body follows its
    /// entity's world pose, so it moves with its parents; a dynamic body is moved only by
    /// physics and by writes to its own transform, and its result is written back as the
    /// local transform relative to its parent.
    pub fn step(&mut self, world: &mut WorldState, dt: f32, events: &mut Vec<Event>) {
        self.sync(world, events);
        if self.links.is_empty() && self.departed.is_empty() {
            self.commands.clear();
            return;
        }
        self.joints.sync(&world.ecs, &mut self.world, |e| {
            self.links.get(e).map(|l| l.body)
        });
        self.apply_commands(events);
        self.world.settings_mut().dt = dt;
        let output = self.world.step().clone();
        for broken in &output.broken_joints {
            let Some(e) = self.joints.entity(broken.joint) else {
                continue;
            };
            if let Ok(mut joint) = world.ecs.get::<&mut Joint>(e) {
                joint.broken = true;
            }
            events.push(Event::Physics(PhysicsEvent::JointBroke {
                entity: to_api(e),
                force: broken.force,
                torque: broken.torque,
            }));
            tracing::warn!(
                entity = %to_api(e),
                "physics: joint broke under {:.1} N, {:.1} N·m",
                broken.force.length(),
                broken.torque.length()
            );
        }
        for handle in &output.quarantined {
            if let Some(e) = self.entity_of.get(handle) {
                events.push(Event::Platform(PlatformEvent::Error {
                    message: format!(
                        "entity {} went non-finite in physics and was frozen (rolled back, disabled)",
                        to_api(*e)
                    ),
                }));
            }
        }
        let named = |h: BodyHandle| {
            let entity = *self.entity_of.get(&h)?;
            let name = world.ecs.get::<&Name>(entity).ok().map(|n| n.0.clone());
            Some(Named { entity, name })
        };
        for line in self.reports.sentences(&output, named) {
            tracing::warn!("{line}");
        }
        let entity =
            |h: &ColliderHandle| self.collider_entity.get(h).or_else(|| self.departed.get(h));
        for contact in &output.events {
            let (Some(a), Some(b)) = (entity(&contact.collider_a), entity(&contact.collider_b))
            else {
                continue;
            };
            let (a, b) = (to_api(*a), to_api(*b));
            if contact.sensor {
                // The sensor is whichever collider is one (`a` when it is gone).
                let b_is_sensor = self
                    .world
                    .collider(contact.collider_b)
                    .is_some_and(onyx_physics::Collider::is_sensor);
                let (sensor, other) = if b_is_sensor { (b, a) } else { (a, b) };
                events.push(Event::Physics(match contact.kind {
                    ContactEventKind::Started => PhysicsEvent::SensorEntered { sensor, other },
                    ContactEventKind::Ended => PhysicsEvent::SensorExited { sensor, other },
                }));
                continue;
            }
            events.push(Event::Physics(match contact.kind {
                ContactEventKind::Started => PhysicsEvent::ContactStarted {
                    a,
                    b,
                    normal: contact.normal,
                    point: contact.points.first().copied().unwrap_or(Vec3::ZERO),
                    impulse: contact.impulse,
                },
                ContactEventKind::Ended => PhysicsEvent::ContactEnded { a, b },
            }));
        }
        self.departed.clear();
        self.write_back(world);
    }

    /// The physics collider for a component (placed and scaled by the caller), or the event that says why there is none (a
    /// model that cannot be loaded is a graphics asset failure naming the file).
    fn collider_desc(
        collider: &Collider,
        assets: &AssetRegistry,
        entity: Entity,
    ) -> Result<ColliderDesc, Event> {
        let error = |message: String| {
            Event::Platform(PlatformEvent::Error {
                message: format!("entity {entity}: collider not created: {message}"),
            })
        };
        let desc = match collider.shape {
            ColliderShape::Sphere { radius } => ColliderDesc::sphere(radius),
            ColliderShape::Box {
                half_extents: [x, y, z],
            } => ColliderDesc::cuboid(x, y, z),
            ColliderShape::Capsule {
                half_height,
                radius,
            } => ColliderDesc::capsule(half_height, radius),
            ColliderShape::Plane => ColliderDesc::half_space(Vec3::Y),
            ColliderShape::ConvexHull { mesh } | ColliderShape::TriMesh { mesh } => {
                let path = assets
                    .mesh_path(mesh)
                    .ok_or_else(|| error(format!("mesh id {} is not a loaded model", mesh.0)))?;
                let data = onyx_render::mesh::load_model_geometry(
                    &assets.resolve(path),
                    &assets.import_settings(path),
                )
                .map_err(|e| {
                    Event::Graphics(GraphicsEvent::AssetFailed {
                        path: path.display().to_string(),
                        message: format!("entity {entity} has no collider: {e}"),
                    })
                })?;
                let points: Vec<Vec3> = data
                    .vertices
                    .iter()
                    .map(|v| Vec3::from(v.position))
                    .collect();
                if matches!(collider.shape, ColliderShape::ConvexHull { .. }) {
                    ColliderDesc::convex_hull(&points).map_err(|e| error(e.to_string()))?
                } else {
                    let triangles = data
                        .indices
                        .chunks_exact(3)
                        .map(|t| [t[0], t[1], t[2]])
                        .collect();
                    ColliderDesc::trimesh(points, triangles).map_err(|e| error(e.to_string()))?
                }
            }
        };
        Ok(desc
            .density(collider.density)
            .restitution(collider.restitution)
            .static_friction(collider.static_friction)
            .dynamic_friction(collider.friction)
            .collision_groups(CollisionGroups::new(collider.memberships, collider.filter))
            .sensor(collider.sensor))
    }

    /// Components → bodies in one pass over the simulated entities: builds new bodies,
    /// rebuilds changed ones, replaces the colliders of bodies whose colliders changed,
    /// removes those whose entity or components are gone, and carries moved transforms and
    /// set velocities over. Unchanged entities cost one comparison each.
    fn sync(&mut self, world: &mut WorldState, events: &mut Vec<Event>) {
        self.sync_epoch += 1;
        let epoch = self.sync_epoch;
        let mut seen = 0;
        if !self.failed.is_empty() {
            self.failed
                .retain(|e, _| world.ecs.satisfies::<&Collider>(*e));
        }
        let mut rebuild: Vec<(hecs::Entity, Transform, Pose, Vec<PlacedCollider>)> = Vec::new();
        let mut replace: Vec<(hecs::Entity, Vec<PlacedCollider>)> = Vec::new();
        for group in compound::gather(&world.ecs) {
            let e = group.owner;
            let Ok(t) = world.ecs.get::<&Transform>(e).map(|t| *t) else {
                continue;
            };
            let rb = world.ecs.get::<&RigidBody>(e).ok().map(|rb| *rb);
            let colliders: Vec<PlacedCollider> = group
                .colliders
                .into_iter()
                .filter(|c| self.failed.get(&c.entity) != Some(&(c.collider, c.placement)))
                .collect();
            if colliders.is_empty() {
                continue;
            }
            let pose = body_pose(world, e, &t);
            let link = match self.links.get_mut(e) {
                Some(link) if link.rigid_body == rb.map(config_only) => link,
                _ => {
                    rebuild.push((e, t, pose, colliders));
                    continue;
                }
            };
            link.seen = epoch;
            seen += 1;
            if !link.carries(&colliders) {
                replace.push((e, colliders));
            }
            let dynamic = rb.is_some_and(|rb| rb.kind == BodyKind::Dynamic);
            let local_moved =
                t.translation != link.written.translation || t.rotation != link.written.rotation;
            let world_moved = pose != link.written_pose;
            // A dynamic body keeps its place in the world when only its parents moved; its
            // local transform is rewritten relative to them.
            let moved = if dynamic { local_moved } else { world_moved };
            if dynamic && world_moved && !local_moved {
                link.parent_moved = true;
                link.settled = false;
            }
            let new_velocity = rb.is_some_and(|rb| {
                (rb.linear_velocity, rb.angular_velocity) != link.written_velocity
            });
            if !moved && !new_velocity {
                continue;
            }
            let Some(body) = self.world.body_mut(link.body) else {
                continue;
            };
            if moved {
                if rb.is_some_and(|rb| rb.kind == BodyKind::Kinematic) {
                    body.set_next_kinematic_pose(pose);
                } else {
                    body.set_pose(pose);
                }
                link.written = t;
                link.written_pose = pose;
                link.settled = false;
            }
            if let (true, Some(rb)) = (new_velocity, rb) {
                body.set_linvel(rb.linear_velocity);
                body.set_angvel(rb.angular_velocity);
                link.written_velocity = (rb.linear_velocity, rb.angular_velocity);
                link.settled = false;
            }
        }
        // Bodies whose entity or components are gone (or changed: rebuilt below).
        if seen != self.links.len() {
            let stale: Vec<hecs::Entity> = self
                .links
                .iter()
                .filter(|(_, link)| link.seen != epoch)
                .map(|(e, _)| e)
                .collect();
            for e in stale {
                self.remove(e);
            }
        }
        for (e, colliders) in replace {
            self.replace_colliders(world, e, &colliders, events);
        }
        for (e, t, pose, colliders) in rebuild {
            self.remove(e);
            let rb = world.ecs.get::<&RigidBody>(e).ok().map(|rb| *rb);
            self.build(world, e, &t, &pose, rb.as_ref(), &colliders, events);
        }
    }

    /// Builds a body for `e` with `colliders` on it; none is made when no collider can be.
    #[allow(clippy::too_many_arguments)]
    fn build(
        &mut self,
        world: &WorldState,
        e: hecs::Entity,
        t: &Transform,
        pose: &Pose,
        rb: Option<&RigidBody>,
        colliders: &[PlacedCollider],
        events: &mut Vec<Event>,
    ) {
        let body = self.world.insert_body(body_desc(rb, pose));
        let attached = self.attach(world, body, colliders, events);
        if attached.is_empty() {
            self.world.remove_body(body);
            return;
        }
        self.apply_mass(body, rb);
        self.entity_of.insert(body, e);
        self.links.insert(
            e,
            Link {
                body,
                rigid_body: rb.copied().map(config_only),
                colliders: attached,
                written: *t,
                written_pose: *pose,
                parent_moved: false,
                written_velocity: rb.map_or((Vec3::ZERO, Vec3::ZERO), |rb| {
                    (rb.linear_velocity, rb.angular_velocity)
                }),
                settled: false,
                seen: self.sync_epoch,
            },
        );
    }

    /// Puts `colliders` on `body`; those that cannot be built are reported (once) and left
    /// out.
    fn attach(
        &mut self,
        world: &WorldState,
        body: BodyHandle,
        colliders: &[PlacedCollider],
        events: &mut Vec<Event>,
    ) -> Vec<(PlacedCollider, ColliderHandle)> {
        let mut attached = Vec::with_capacity(colliders.len());
        for placed in colliders {
            let entity = to_api(placed.entity);
            let desc =
                Self::collider_desc(&placed.collider, &world.assets, entity).and_then(|desc| {
                    desc.scaled(placed.placement.scale).map_err(|message| {
                        Event::Platform(PlatformEvent::Error {
                            message: format!(
                                "entity {entity}: collider not created: its scale {} {message}",
                                placed.placement.scale
                            ),
                        })
                    })
                });
            let (desc, made_uniform) = match desc {
                Ok(built) => built,
                Err(event) => {
                    events.push(event);
                    self.failed
                        .insert(placed.entity, (placed.collider, placed.placement));
                    continue;
                }
            };
            self.failed.remove(&placed.entity);
            if made_uniform && self.warned_scale.insert(placed.entity) {
                let name = world
                    .ecs
                    .get::<&Name>(placed.entity)
                    .ok()
                    .map(|n| n.0.clone());
                tracing::warn!(
                    entity = %entity,
                    "physics: {} has a non-uniform scale {}; its sphere or capsule collider \
                     stays round, scaled by the largest component",
                    name.map_or_else(|| format!("entity {entity}"), |n| format!("`{n}`")),
                    placed.placement.scale
                );
            }
            let Some(handle) = self
                .world
                .insert_collider(desc.local_pose(placed.placement.pose), body)
            else {
                continue;
            };
            self.collider_entity.insert(handle, placed.entity);
            attached.push((*placed, handle));
        }
        attached
    }

    /// Swaps the colliders of `e`'s body for `colliders` (its motion is kept); the body goes
    /// when none of them can be built.
    fn replace_colliders(
        &mut self,
        world: &WorldState,
        e: hecs::Entity,
        colliders: &[PlacedCollider],
        events: &mut Vec<Event>,
    ) {
        let Some(link) = self.links.get_mut(e) else {
            return;
        };
        let body = link.body;
        for (placed, handle) in std::mem::take(&mut link.colliders) {
            self.world.remove_collider(handle);
            self.collider_entity.remove(&handle);
            self.departed.insert(handle, placed.entity);
        }
        if let Some(b) = self.world.body_mut(body) {
            b.set_mass_properties(None);
        }
        let attached = self.attach(world, body, colliders, events);
        if attached.is_empty() {
            self.remove(e);
            return;
        }
        let rb = world.ecs.get::<&RigidBody>(e).ok().map(|rb| *rb);
        self.apply_mass(body, rb.as_ref());
        if let Some(link) = self.links.get_mut(e) {
            link.colliders = attached;
        }
    }

    /// A `RigidBody` with a mass keeps the shape of its colliders' inertia, scaled to it.
    fn apply_mass(&mut self, body: BodyHandle, rb: Option<&RigidBody>) {
        let (Some(rb), Some(b)) = (rb, self.world.body_mut(body)) else {
            return;
        };
        let mp = *b.mass_properties();
        if rb.mass > 0.0 && mp.mass > 0.0 {
            let k = rb.mass / mp.mass;
            b.set_mass_properties(Some(MassProperties {
                mass: rb.mass,
                local_com: mp.local_com,
                inertia: mp.inertia * k,
            }));
        }
    }

    fn remove(&mut self, e: hecs::Entity) {
        if let Some(link) = self.links.remove(e) {
            for (placed, handle) in &link.colliders {
                self.collider_entity.remove(handle);
                self.departed.insert(*handle, placed.entity);
            }
            self.world.remove_body(link.body);
            self.entity_of.remove(&link.body);
        }
    }

    fn apply_commands(&mut self, events: &mut Vec<Event>) {
        for (entity, command) in std::mem::take(&mut self.commands) {
            let body = to_hecs(entity)
                .and_then(|e| self.links.get(e))
                .and_then(|link| self.world.body_mut(link.body));
            let Some(body) = body else {
                events.push(Event::Platform(PlatformEvent::Error {
                    message: format!(
                        "entity {entity} has no physics body; its force or impulse was dropped"
                    ),
                }));
                continue;
            };
            match command {
                PhysicsCommand::Force(f) => body.add_force(f.into()),
                PhysicsCommand::Torque(t) => body.add_torque(t.into()),
                PhysicsCommand::Impulse(j) => body.apply_impulse(j.into()),
                PhysicsCommand::Velocity { linear, angular } => {
                    body.set_linvel(linear.into());
                    body.set_angvel(angular.into());
                }
            }
        }
    }

    /// Body poses and state back into the components: a root's transform gets the body's
    /// world pose; an entity with a parent gets the local transform that puts it there
    /// (parents before children, so each sees its parent's new pose).
    fn write_back(&mut self, world: &mut WorldState) {
        let mut with_parent = Vec::new();
        for (e, link) in self.links.iter_mut() {
            let Some(body) = self.world.body(link.body) else {
                continue;
            };
            let at_rest = body.is_sleeping() || body.body_type() == BodyType::Static;
            if link.settled && at_rest {
                continue;
            }
            link.settled = at_rest && !link.parent_moved;
            let pose = Pose {
                translation: body.translation(),
                rotation: body.rotation(),
            };
            // A static or kinematic body that ended where its entity put it has no new pose
            // (writing it back through a parent's inverse would only add rounding).
            let moved_by_physics =
                body.body_type() == BodyType::Dynamic || pose != link.written_pose;
            if moved_by_physics && world_pose::parent_in(&world.ecs, e).is_some() {
                with_parent.push(e);
                continue;
            }
            let local = moved_by_physics.then_some((pose.translation, pose.rotation));
            Self::write_body(world, e, link, body, local);
        }
        if with_parent.is_empty() {
            return;
        }
        with_parent.sort_by_cached_key(|e| world_pose::ancestry(&world.ecs, *e).len());
        for e in with_parent {
            let Some(link) = self.links.get_mut(e) else {
                continue;
            };
            let Some(body) = self.world.body(link.body) else {
                continue;
            };
            let parent_world = world_pose::parent_world_now(&world.ecs, e);
            let body_world =
                Affine3A::from_rotation_translation(body.rotation(), body.translation());
            let Some(local) = world_pose::local_for(parent_world, body_world) else {
                continue; // a parent scaled to zero: nothing can put the body there
            };
            Self::write_body(
                world,
                e,
                link,
                body,
                Some((local.translation, local.rotation)),
            );
        }
    }

    /// Writes one body's result: its local pose (`translation`, `rotation`), when it has a
    /// new one, into the entity's transform; velocities and contact state into its
    /// `RigidBody`.
    fn write_body(
        world: &mut WorldState,
        e: hecs::Entity,
        link: &mut Link,
        body: &onyx_physics::RigidBody,
        local: Option<(Vec3, Quat)>,
    ) {
        let Ok((t, rb)) = world
            .ecs
            .query_one_mut::<(&mut Transform, Option<&mut RigidBody>)>(e)
        else {
            return;
        };
        if let Some((translation, rotation)) = local {
            t.translation = translation;
            t.rotation = rotation;
        }
        link.written = *t;
        link.written_pose = Pose {
            translation: body.translation(),
            rotation: body.rotation(),
        };
        link.parent_moved = false;
        if let Some(rb) = rb {
            rb.linear_velocity = body.linvel();
            rb.angular_velocity = body.angvel();
            rb.sleeping = body.is_sleeping();
            rb.grounded = body.is_grounded();
            rb.contact_normal = body.last_contact_normal().unwrap_or(Vec3::ZERO);
            link.written_velocity = (rb.linear_velocity, rb.angular_velocity);
        }
        if local.is_some() {
            world.hierarchy.moved(e);
        }
    }
}

/// The part of a `RigidBody` the user sets (not the state the host writes back).
fn config_only(rb: RigidBody) -> RigidBody {
    RigidBody {
        linear_velocity: Vec3::ZERO,
        angular_velocity: Vec3::ZERO,
        sleeping: false,
        grounded: false,
        contact_normal: Vec3::ZERO,
        ..rb
    }
}
