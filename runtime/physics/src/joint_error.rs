//! [`JointError`]: why a joint could not be inserted or changed.

use crate::body_handle::BodyHandle;

/// A joint the world refused (see [`crate::PhysicsWorld::insert_joint`]).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum JointError {
    /// A value of the description is out of its range.
    #[error("joint `{field}` {message}")]
    Invalid {
        /// The field (`limits`, `motor.max_force`, `frame_a`, …).
        field: &'static str,
        /// What is wrong, completing "`field` …".
        message: String,
    },
    /// A body it names is not in the world.
    #[error("joint names body {0:?}, which is not in the world")]
    NoSuchBody(BodyHandle),
    /// Both sides are the same body.
    #[error("a joint needs two different bodies, got body {0:?} twice")]
    SameBody(BodyHandle),
    /// The joint handle does not resolve.
    #[error("no such joint")]
    NoSuchJoint,
}
