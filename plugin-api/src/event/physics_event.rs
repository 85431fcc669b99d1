//! [`PhysicsEvent`]: events whose source is the physics engine.

use glam::Vec3;

use crate::Entity;

/// What the physics engine reports: contacts starting and ending (every start is followed by
/// one end), sensors entered and left, joints breaking.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum PhysicsEvent {
    /// `a` and `b` started touching.
    ContactStarted {
        /// First entity (the normal points away from it).
        a: Entity,
        /// Second entity.
        b: Entity,
        /// Contact normal from `a` to `b`.
        normal: Vec3,
        /// A contact point, world space.
        point: Vec3,
        /// Normal impulse of the step it started in, N·s.
        impulse: f32,
    },
    /// `a` and `b` stopped touching (or one of them was removed).
    ContactEnded {
        /// First entity.
        a: Entity,
        /// Second entity.
        b: Entity,
    },
    /// `other` started overlapping the sensor collider of `sensor` (reported in the step
    /// after the one that moved it in).
    SensorEntered {
        /// The entity whose collider is the sensor.
        sensor: Entity,
        /// The entity that entered.
        other: Entity,
    },
    /// `other` stopped overlapping `sensor` (or one of them was removed).
    SensorExited {
        /// The sensor's entity.
        sensor: Entity,
        /// The entity that left.
        other: Entity,
    },
    /// The joint on `entity` broke: the force or torque it carried passed its break
    /// threshold (its [`Joint::broken`](crate::Joint::broken) is now set). Reported once.
    JointBroke {
        /// The entity holding the `Joint` component.
        entity: Entity,
        /// The force the joint carried when it broke, N (world axes).
        force: Vec3,
        /// The torque it carried, N·m.
        torque: Vec3,
    },
}
