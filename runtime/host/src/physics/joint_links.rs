//! [`JointLinks`]: `Joint` components → physics joints, made at the bodies' poses when the
//! component is written, remade when it changes, removed with it; broken joints written back.

use std::collections::{HashMap, HashSet};

use onyx_physics::glam::{Quat, Vec3};
use onyx_physics::{BodyHandle, JointDesc, JointHandle, PhysicsWorld, Pose};
use onyx_plugin_api::{Joint, JointKind, JointMotor, JointTarget};

use crate::entity_id::{to_api, to_hecs};

/// What a physics joint was made from: a change remakes it.
type BuiltFrom = (Joint, Option<BodyHandle>, BodyHandle);

#[derive(Debug, Default)]
pub(super) struct JointLinks {
    links: HashMap<hecs::Entity, (JointHandle, BuiltFrom)>,
    entity_of: HashMap<JointHandle, hecs::Entity>,
    /// Joints the engine refused, kept so each is reported once (until the component
    /// changes).
    refused: HashMap<hecs::Entity, BuiltFrom>,
}

/// `0` means "never" in the component; the engine takes infinity.
fn threshold(value: f32) -> f32 {
    if value > 0.0 {
        value
    } else {
        f32::INFINITY
    }
}

/// The engine's description of `joint` between `a` (`None`: the world) and `b` (this
/// entity's body), at their current poses: the other side's axis is this side's axis as it
/// lies in the world now, so a hinge's or slider's coordinate starts at 0.
pub(super) fn joint_desc(joint: &Joint, pose_a: Option<Pose>, pose_b: Pose) -> JointDesc {
    let axis = Vec3::from(joint.axis).normalize_or_zero();
    let frame_rot_b = Quat::from_rotation_arc(Vec3::X, axis);
    let world_rot = pose_b.rotation * frame_rot_b;
    let frame_rot_a = match pose_a {
        Some(pa) => pa.rotation.inverse() * world_rot,
        None => world_rot,
    };
    let motor = |desc: JointDesc| match joint.motor {
        JointMotor::Off => desc,
        JointMotor::Velocity { speed, max_force } => desc.motor_velocity(speed, max_force),
        JointMotor::Position {
            target,
            hertz,
            damping_ratio,
            max_force,
        } => desc.motor_position(target, hertz, damping_ratio, max_force),
    };
    let spring = |desc: JointDesc| {
        if joint.spring_hertz > 0.0 {
            desc.spring(
                joint.spring_rest,
                joint.spring_hertz,
                joint.spring_damping_ratio,
            )
        } else {
            desc
        }
    };
    let limits = |desc: JointDesc| {
        if joint.limits {
            desc.limits(joint.lower, joint.upper)
        } else {
            desc
        }
    };
    let desc = match joint.kind {
        JointKind::Fixed => JointDesc::fixed(),
        JointKind::Revolute => spring(motor(limits(JointDesc::revolute(Vec3::X)))),
        JointKind::Prismatic => spring(motor(limits(JointDesc::prismatic(Vec3::X)))),
        JointKind::Spherical { cone } => {
            let d = limits(JointDesc::spherical());
            if cone > 0.0 {
                d.cone_limit(cone)
            } else {
                d
            }
        }
        JointKind::Distance { min, max } => spring(JointDesc::distance(max).limits(min, max)),
    };
    desc.local_frame_a(Pose::new(Vec3::from(joint.other_anchor), frame_rot_a))
        .local_frame_b(Pose::new(Vec3::from(joint.anchor), frame_rot_b))
        .break_force(threshold(joint.break_force))
        .break_torque(threshold(joint.break_torque))
        .collide_connected(joint.collide_connected)
}

impl JointLinks {
    /// Makes, remakes and removes physics joints so that each entity with a `Joint` (not
    /// broken) and a body, whose other side has a body (or is the world), has one. `body_of`
    /// gives an entity's body.
    pub fn sync(
        &mut self,
        ecs: &hecs::World,
        world: &mut PhysicsWorld,
        body_of: impl Fn(hecs::Entity) -> Option<BodyHandle>,
    ) {
        let mut present = HashSet::new();
        let mut make = Vec::new();
        for (e, joint) in ecs.query::<(hecs::Entity, &Joint)>().iter() {
            if joint.broken {
                continue;
            }
            let Some(b) = body_of(e) else {
                continue;
            };
            let a = match joint.other {
                JointTarget::World => None,
                JointTarget::Body(other) => match to_hecs(other).and_then(&body_of) {
                    Some(a) => Some(a),
                    None => continue,
                },
            };
            present.insert(e);
            let key = (*joint, a, b);
            let current = self
                .links
                .get(&e)
                .is_some_and(|(h, from)| *from == key && world.joint(*h).is_some());
            if current || self.refused.get(&e) == Some(&key) {
                continue;
            }
            make.push((e, key));
        }
        let gone: Vec<hecs::Entity> = self
            .links
            .keys()
            .copied()
            .filter(|e| !present.contains(e))
            .collect();
        for e in gone {
            self.remove(e, world);
        }
        self.refused.retain(|e, _| present.contains(e));
        for (e, key) in make {
            self.remove(e, world);
            let (joint, a, b) = key;
            let pose = |h: BodyHandle| world.body(h).map(|body| body.pose());
            let Some(pose_b) = pose(b) else {
                continue;
            };
            let pose_a = a.and_then(pose);
            let desc = joint_desc(&joint, pose_a, pose_b);
            match world.insert_joint(desc, a, b) {
                Ok(handle) => {
                    self.refused.remove(&e);
                    self.entity_of.insert(handle, e);
                    self.links.insert(e, (handle, key));
                }
                Err(error) => {
                    tracing::warn!(entity = %to_api(e), "physics: joint refused: {error}");
                    self.refused.insert(e, key);
                }
            }
        }
    }

    fn remove(&mut self, e: hecs::Entity, world: &mut PhysicsWorld) {
        if let Some((handle, _)) = self.links.remove(&e) {
            world.remove_joint(handle);
            self.entity_of.remove(&handle);
        }
    }

    /// The entity whose joint this is.
    pub fn handle(&self, e: hecs::Entity) -> Option<JointHandle> {
        self.links.get(&e).map(|(h, _)| *h)
    }

    pub fn entity(&self, handle: JointHandle) -> Option<hecs::Entity> {
        self.entity_of.get(&handle).copied()
    }
}
