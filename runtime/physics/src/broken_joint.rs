//! [`BrokenJoint`]: a joint whose force or torque passed its break threshold this step.

use glam::Vec3;

use crate::joint_handle::JointHandle;

/// A joint that broke this step (in [`crate::StepOutput::broken_joints`], once): it no longer
/// acts. The force and torque are what it had to carry when it broke.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BrokenJoint {
    /// The joint.
    pub joint: JointHandle,
    /// Its constraint force on body B, N.
    pub force: Vec3,
    /// Its constraint torque on body B, N·m.
    pub torque: Vec3,
}
