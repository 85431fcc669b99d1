//! [`JointSpec`]: one joint, engine-neutral, as [`crate::engine::Engine::add_joint`] takes it.
//! Each kind maps onto the joint of the same name in both engines (rapier: impulse joints,
//! contacts between the joined bodies off as Onyx has them by default).

use onyx_physics::glam::Vec3;

use crate::engine::BodyId;

/// A velocity motor on a hinge: toward `speed` (rad/s) with at most `max_torque` (N·m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VelocityMotor {
    /// Target relative angular speed about the axis, rad/s.
    pub speed: f32,
    /// Largest torque, N·m.
    pub max_torque: f32,
}

/// What the joint removes. Axes are in each body's frame (the same on both sides).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum JointKindSpec {
    /// A hinge about `axis`, with angle limits (rad) and a velocity motor.
    Revolute {
        /// Hinge axis.
        axis: Vec3,
        /// Angle limits `[lower, upper]`, rad.
        limits: Option<[f32; 2]>,
        /// Velocity motor.
        motor: Option<VelocityMotor>,
    },
    /// A slider along `axis` with translation limits (m).
    Prismatic {
        /// Slider axis.
        axis: Vec3,
        /// Translation limits `[lower, upper]`, m.
        limits: Option<[f32; 2]>,
    },
    /// A ball joint; `axis` is the swing axis that the cone and the twist refer to.
    Spherical {
        /// Swing axis.
        axis: Vec3,
        /// Largest swing of B's axis from A's, rad (rapier: limits ±cone about both axes
        /// across the swing axis, its nearest equivalent).
        cone: Option<f32>,
        /// Twist limits about the axis `[lower, upper]`, rad.
        twist: Option<[f32; 2]>,
    },
}

/// One joint between body `a` (`None`: the world) and body `b`, at an anchor on each side
/// (in that body's frame; a world point when `a` is the world).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointSpec {
    /// Kind, limits and motor.
    pub kind: JointKindSpec,
    /// First body, or the world.
    pub a: Option<BodyId>,
    /// Second body.
    pub b: BodyId,
    /// Anchor on `a` (world point for the world).
    pub anchor_a: Vec3,
    /// Anchor on `b`.
    pub anchor_b: Vec3,
}

impl JointSpec {
    /// A hinge about `axis`.
    #[must_use]
    pub fn revolute(a: Option<BodyId>, b: BodyId, axis: Vec3, anchors: [Vec3; 2]) -> Self {
        Self {
            kind: JointKindSpec::Revolute {
                axis,
                limits: None,
                motor: None,
            },
            a,
            b,
            anchor_a: anchors[0],
            anchor_b: anchors[1],
        }
    }

    /// A slider along `axis`.
    #[must_use]
    pub fn prismatic(a: Option<BodyId>, b: BodyId, axis: Vec3, anchors: [Vec3; 2]) -> Self {
        Self {
            kind: JointKindSpec::Prismatic { axis, limits: None },
            a,
            b,
            anchor_a: anchors[0],
            anchor_b: anchors[1],
        }
    }

    /// A ball joint whose swing axis is `axis`.
    #[must_use]
    pub fn spherical(a: Option<BodyId>, b: BodyId, axis: Vec3, anchors: [Vec3; 2]) -> Self {
        Self {
            kind: JointKindSpec::Spherical {
                axis,
                cone: None,
                twist: None,
            },
            a,
            b,
            anchor_a: anchors[0],
            anchor_b: anchors[1],
        }
    }

    /// Limits of a hinge's angle, a slider's translation or a ball joint's twist.
    #[must_use]
    pub fn limits(mut self, lower: f32, upper: f32) -> Self {
        match &mut self.kind {
            JointKindSpec::Revolute { limits, .. } | JointKindSpec::Prismatic { limits, .. } => {
                *limits = Some([lower, upper]);
            }
            JointKindSpec::Spherical { twist, .. } => *twist = Some([lower, upper]),
        }
        self
    }

    /// A ball joint's cone limit (no effect on other kinds).
    #[must_use]
    pub fn cone(mut self, angle: f32) -> Self {
        if let JointKindSpec::Spherical { cone, .. } = &mut self.kind {
            *cone = Some(angle);
        }
        self
    }

    /// A hinge's velocity motor (no effect on other kinds).
    #[must_use]
    pub fn motor(mut self, speed: f32, max_torque: f32) -> Self {
        if let JointKindSpec::Revolute { motor, .. } = &mut self.kind {
            *motor = Some(VelocityMotor { speed, max_torque });
        }
        self
    }
}
