//! [`Joint`]: a joint in the world — its description, the bodies it joins, the impulses it
//! carried last step (warm start, reaction force) and whether it broke.

use glam::Vec3;

use crate::body_handle::BodyHandle;
use crate::joint_desc::JointDesc;

/// Accumulated impulses of a joint's rows, kept from step to step to warm-start the solver.
/// Block rows (the anchor point, the line of a slider, the orientation locks) are per row of
/// the block; drive and limit rows are scalars along the free axis.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct JointImpulses {
    /// The linear block (point: world x, y, z; slider: its two cross axes).
    pub linear: [f32; 3],
    /// The angular block (weld and slider: world x, y, z; hinge: its two cross axes).
    pub angular: [f32; 3],
    /// Spring along or about the free axis.
    pub spring: f32,
    /// Motor along or about the free axis.
    pub motor: f32,
    /// Lower and upper limit of the free coordinate (ball joint: of its twist).
    pub lower: f32,
    pub upper: f32,
    /// Ball joint's cone limit; rod's length row.
    pub cone: f32,
}

/// A joint between body A (or the world) and body B. Insert with
/// [`crate::PhysicsWorld::insert_joint`].
#[derive(Clone, Debug)]
pub struct Joint {
    pub(crate) desc: JointDesc,
    pub(crate) body_a: Option<BodyHandle>,
    pub(crate) body_b: BodyHandle,
    pub(crate) impulses: JointImpulses,
    pub(crate) force: Vec3,
    pub(crate) torque: Vec3,
    pub(crate) broken: bool,
}

impl Joint {
    /// Its description (kind, frames, limits, motor, spring, break thresholds).
    pub fn desc(&self) -> &JointDesc {
        &self.desc
    }

    /// Body A, or `None` for the world.
    #[must_use]
    pub fn body_a(&self) -> Option<BodyHandle> {
        self.body_a
    }

    /// Body B.
    #[must_use]
    pub fn body_b(&self) -> BodyHandle {
        self.body_b
    }

    /// The force the joint applied to body B over the last step, N (A got the opposite).
    #[must_use]
    pub fn reaction_force(&self) -> Vec3 {
        self.force
    }

    /// The torque the joint applied to body B over the last step (its angular rows, about
    /// B's centre of mass; the anchor force's moment not included), N·m.
    #[must_use]
    pub fn reaction_torque(&self) -> Vec3 {
        self.torque
    }

    /// Whether it broke (its force or torque passed its threshold): a broken joint no
    /// longer acts and is reported once in `StepOutput::broken_joints`.
    #[must_use]
    pub fn is_broken(&self) -> bool {
        self.broken
    }
}
