//! [`JointDesc`]: what a joint holds together and how — its kind with limits, motor and
//! spring, the frame it attaches at on each body, when it breaks, and whether the two bodies
//! still collide.

use glam::{Quat, Vec3};

use crate::joint_error::JointError;
use crate::pose::Pose;

/// A motor's goal along or about a joint's free axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MotorTarget {
    /// Drive the relative velocity (rad/s or m/s) to this speed.
    Velocity(f32),
    /// Drive the coordinate (rad or m) to this value like a spring-damper of `hertz` and
    /// `damping_ratio` (a servo): the force it takes is bounded by the motor's `max_force`.
    Position {
        /// The angle (rad) or translation (m) to reach.
        target: f32,
        /// Stiffness as a natural frequency, Hz (> 0).
        hertz: f32,
        /// Damping ratio (1: critically damped).
        damping_ratio: f32,
    },
}

/// A motor on a joint's free axis: a goal and the largest force (N, prismatic) or torque
/// (N·m, revolute) it may use.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointMotor {
    /// What it drives toward.
    pub target: MotorTarget,
    /// Largest force or torque, N or N·m (≥ 0).
    pub max_force: f32,
}

/// A spring on a joint's free coordinate, pulling it toward `rest` with no force bound.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointSpring {
    /// Where it rests: an angle (rad), a translation (m) or a length (m).
    pub rest: f32,
    /// Stiffness as a natural frequency of the bodies it joins, Hz (> 0).
    pub hertz: f32,
    /// Damping ratio (1: critically damped, 0: undamped).
    pub damping_ratio: f32,
}

/// Lower and upper bound of a joint coordinate: radians for angles, metres for translations
/// and lengths.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointLimits {
    /// Smallest value.
    pub lower: f32,
    /// Largest value (≥ `lower`).
    pub upper: f32,
}

/// Which motions a joint removes. Each joint's frame on body A and on body B (see
/// [`JointDesc`]) carries its axis as the frame's X axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum JointKind {
    /// Welds the two frames together: no relative motion.
    Fixed,
    /// A hinge: the anchors coincide and the X axes stay aligned; the bodies turn about it.
    /// Its coordinate is the angle of frame B about X relative to frame A, in (−π, π].
    Revolute {
        /// Angle limits, radians, within (−π, π].
        limits: Option<JointLimits>,
        /// A motor about the hinge.
        motor: Option<JointMotor>,
        /// A spring about the hinge.
        spring: Option<JointSpring>,
    },
    /// A slider: the frames keep their orientation and B's anchor stays on A's X axis. Its
    /// coordinate is the translation of B's anchor along A's X axis, metres.
    Prismatic {
        /// Translation limits, metres.
        limits: Option<JointLimits>,
        /// A motor along the axis.
        motor: Option<JointMotor>,
        /// A spring along the axis.
        spring: Option<JointSpring>,
    },
    /// A ball joint: the anchors coincide, the bodies turn freely about it. The swing of B's
    /// X axis away from A's can be bounded by a cone, the twist about it by limits.
    Spherical {
        /// Largest angle between the two X axes, radians, in (0, π].
        cone: Option<f32>,
        /// Twist limits about B's X axis, radians, within (−π, π].
        twist: Option<JointLimits>,
    },
    /// Keeps the anchors' distance within `[min, max]` (a rod when equal, a rope from 0),
    /// optionally pulled toward a rest length by a spring. Its coordinate is the distance.
    Distance {
        /// Shortest distance, metres (≥ 0).
        min: f32,
        /// Longest distance, metres (≥ `min`).
        max: f32,
        /// A spring toward a rest length (acts between `min` and `max`).
        spring: Option<JointSpring>,
    },
}

/// A joint to be inserted with [`crate::PhysicsWorld::insert_joint`].
///
/// ```
/// use onyx_physics::{glam::Vec3, ColliderDesc, JointDesc, PhysicsWorld, RigidBodyDesc};
///
/// let mut world = PhysicsWorld::default();
/// // A 1 m pendulum hung from the world at (0, 2, 0).
/// let bob = world.insert_body(RigidBodyDesc::dynamic().translation(Vec3::new(1.0, 2.0, 0.0)));
/// world.insert_collider(ColliderDesc::sphere(0.1), bob);
/// let hinge = JointDesc::revolute(Vec3::Z)
///     .local_anchor_a(Vec3::new(0.0, 2.0, 0.0)) // on the world: a world point
///     .local_anchor_b(Vec3::new(-1.0, 0.0, 0.0)); // on the bob: 1 m to its left
/// world.insert_joint(hinge, None, bob).unwrap();
/// for _ in 0..30 {
///     world.step();
/// }
/// let p = world.body(bob).unwrap().translation();
/// assert!(((p - Vec3::new(0.0, 2.0, 0.0)).length() - 1.0).abs() < 1e-3);
/// ```
///
/// The frame on each side is a pose in that body's frame (for the world: in world space):
/// its translation is the anchor, its X axis the joint axis. Anchors default to each body's
/// origin, axes to the one given to the constructor.
#[derive(Clone, Copy, Debug, PartialEq)]
#[must_use]
pub struct JointDesc {
    /// What it removes, with limits, motor and spring.
    pub kind: JointKind,
    /// Its frame on body A (world space when A is the world).
    pub frame_a: Pose,
    /// Its frame on body B.
    pub frame_b: Pose,
    /// Constraint force past which it breaks, N (infinity: never).
    pub break_force: f32,
    /// Constraint torque past which it breaks, N·m (infinity: never).
    pub break_torque: f32,
    /// Whether the two bodies still collide with each other (default: they do not).
    pub collide_connected: bool,
}

/// The rotation whose X axis is `axis` (the joint frame of an axis).
fn frame_of_axis(axis: Vec3) -> Quat {
    let n = axis.normalize_or_zero();
    if n == Vec3::ZERO || !n.is_finite() {
        // Refused by `validate` (kept as NaN so that it is).
        return Quat::from_xyzw(f32::NAN, 0.0, 0.0, 0.0);
    }
    Quat::from_rotation_arc(Vec3::X, n)
}

impl JointDesc {
    fn new(kind: JointKind, axis: Vec3) -> Self {
        let rotation = frame_of_axis(axis);
        Self {
            kind,
            frame_a: Pose::new(Vec3::ZERO, rotation),
            frame_b: Pose::new(Vec3::ZERO, rotation),
            break_force: f32::INFINITY,
            break_torque: f32::INFINITY,
            collide_connected: false,
        }
    }

    /// A weld: the bodies keep the relative pose their frames give.
    pub fn fixed() -> Self {
        Self::new(JointKind::Fixed, Vec3::X)
    }

    /// A hinge about `axis` (in each body's frame).
    pub fn revolute(axis: Vec3) -> Self {
        Self::new(
            JointKind::Revolute {
                limits: None,
                motor: None,
                spring: None,
            },
            axis,
        )
    }

    /// A slider along `axis` (in each body's frame).
    pub fn prismatic(axis: Vec3) -> Self {
        Self::new(
            JointKind::Prismatic {
                limits: None,
                motor: None,
                spring: None,
            },
            axis,
        )
    }

    /// A ball joint (its swing axis, for a cone limit, is X; see [`JointDesc::local_axis_a`]).
    pub fn spherical() -> Self {
        Self::new(
            JointKind::Spherical {
                cone: None,
                twist: None,
            },
            Vec3::X,
        )
    }

    /// A rod: the anchors stay `length` metres apart.
    pub fn distance(length: f32) -> Self {
        Self::new(
            JointKind::Distance {
                min: length,
                max: length,
                spring: None,
            },
            Vec3::X,
        )
    }

    /// A rope: the anchors at most `length` metres apart, free when closer.
    pub fn rope(length: f32) -> Self {
        Self::new(
            JointKind::Distance {
                min: 0.0,
                max: length,
                spring: None,
            },
            Vec3::X,
        )
    }

    /// The anchor on body A, in its frame (a world point when A is the world).
    pub fn local_anchor_a(mut self, anchor: Vec3) -> Self {
        self.frame_a.translation = anchor;
        self
    }

    /// The anchor on body B, in its frame.
    pub fn local_anchor_b(mut self, anchor: Vec3) -> Self {
        self.frame_b.translation = anchor;
        self
    }

    /// The joint axis on body A, in its frame.
    pub fn local_axis_a(mut self, axis: Vec3) -> Self {
        self.frame_a.rotation = frame_of_axis(axis);
        self
    }

    /// The joint axis on body B, in its frame.
    pub fn local_axis_b(mut self, axis: Vec3) -> Self {
        self.frame_b.rotation = frame_of_axis(axis);
        self
    }

    /// The whole frame on body A (anchor and orientation; X is the axis).
    pub fn local_frame_a(mut self, frame: Pose) -> Self {
        self.frame_a = frame;
        self
    }

    /// The whole frame on body B.
    pub fn local_frame_b(mut self, frame: Pose) -> Self {
        self.frame_b = frame;
        self
    }

    /// Limits of the coordinate: the hinge angle (rad), the slider translation (m), the
    /// distance (m), or a ball joint's twist (rad). No effect on a fixed joint.
    pub fn limits(mut self, lower: f32, upper: f32) -> Self {
        let l = Some(JointLimits { lower, upper });
        match &mut self.kind {
            JointKind::Revolute { limits, .. } | JointKind::Prismatic { limits, .. } => {
                *limits = l;
            }
            JointKind::Spherical { twist, .. } => *twist = l,
            JointKind::Distance { min, max, .. } => {
                *min = lower;
                *max = upper;
            }
            JointKind::Fixed => {}
        }
        self
    }

    /// A motor on a hinge or a slider (no effect on other kinds).
    pub fn motor(mut self, m: JointMotor) -> Self {
        if let JointKind::Revolute { motor, .. } | JointKind::Prismatic { motor, .. } =
            &mut self.kind
        {
            *motor = Some(m);
        }
        self
    }

    /// A velocity motor: toward `speed` (rad/s or m/s) with at most `max_force`.
    pub fn motor_velocity(self, speed: f32, max_force: f32) -> Self {
        self.motor(JointMotor {
            target: MotorTarget::Velocity(speed),
            max_force,
        })
    }

    /// A position motor (servo): toward `target` (rad or m) like a spring of `hertz` and
    /// `damping_ratio`, with at most `max_force`.
    pub fn motor_position(
        self,
        target: f32,
        hertz: f32,
        damping_ratio: f32,
        max_force: f32,
    ) -> Self {
        self.motor(JointMotor {
            target: MotorTarget::Position {
                target,
                hertz,
                damping_ratio,
            },
            max_force,
        })
    }

    /// A spring on a hinge, a slider or a distance joint (no effect on other kinds).
    pub fn spring(mut self, rest: f32, hertz: f32, damping_ratio: f32) -> Self {
        let s = Some(JointSpring {
            rest,
            hertz,
            damping_ratio,
        });
        match &mut self.kind {
            JointKind::Revolute { spring, .. }
            | JointKind::Prismatic { spring, .. }
            | JointKind::Distance { spring, .. } => *spring = s,
            JointKind::Fixed | JointKind::Spherical { .. } => {}
        }
        self
    }

    /// A ball joint's cone limit: B's X axis stays within `angle` radians of A's.
    pub fn cone_limit(mut self, angle: f32) -> Self {
        if let JointKind::Spherical { cone, .. } = &mut self.kind {
            *cone = Some(angle);
        }
        self
    }

    /// Breaks when its constraint force passes `force` newtons.
    pub fn break_force(mut self, force: f32) -> Self {
        self.break_force = force;
        self
    }

    /// Breaks when its constraint torque passes `torque` newton-metres.
    pub fn break_torque(mut self, torque: f32) -> Self {
        self.break_torque = torque;
        self
    }

    /// Whether the joined bodies still collide with each other.
    pub fn collide_connected(mut self, on: bool) -> Self {
        self.collide_connected = on;
        self
    }

    /// Checks every value: finite frames with unit rotations, ordered limits within their
    /// range, positive stiffness, non-negative forces and lengths.
    ///
    /// # Errors
    /// [`JointError::Invalid`] naming the first field that is not.
    pub fn validate(&self) -> Result<(), JointError> {
        let bad =
            |field: &'static str, message: String| Err(JointError::Invalid { field, message });
        for (field, frame) in [("frame_a", &self.frame_a), ("frame_b", &self.frame_b)] {
            if !frame.is_finite() || (frame.rotation.length() - 1.0).abs() > 1e-3 {
                return bad(
                    field,
                    format!("must be finite with a unit rotation (a non-zero axis), got {frame:?}"),
                );
            }
        }
        for (field, v) in [
            ("break_force", self.break_force),
            ("break_torque", self.break_torque),
        ] {
            if v.is_nan() || v <= 0.0 {
                return bad(
                    field,
                    format!("must be > 0 (infinity: never breaks), got {v}"),
                );
            }
        }
        let angle = |field, l: &Option<JointLimits>| -> Result<(), JointError> {
            if let Some(l) = l {
                let pi = std::f32::consts::PI;
                if !(l.lower.is_finite() && l.upper.is_finite() && l.lower <= l.upper)
                    || l.lower < -pi
                    || l.upper > pi
                {
                    return bad(
                        field,
                        format!(
                            "must be finite, lower ≤ upper, within [−π, π], got {} … {}",
                            l.lower, l.upper
                        ),
                    );
                }
            }
            Ok(())
        };
        let drive =
            |motor: &Option<JointMotor>, spring: &Option<JointSpring>| -> Result<(), JointError> {
                if let Some(m) = motor {
                    if m.max_force.is_nan() || m.max_force < 0.0 {
                        return bad(
                            "motor.max_force",
                            format!("must be ≥ 0, got {}", m.max_force),
                        );
                    }
                    match m.target {
                        MotorTarget::Velocity(v) if !v.is_finite() => {
                            return bad("motor.target", format!("must be finite, got {v}"));
                        }
                        MotorTarget::Position {
                            target,
                            hertz,
                            damping_ratio,
                        } if !(target.is_finite()
                            && hertz.is_finite()
                            && hertz > 0.0
                            && damping_ratio.is_finite()
                            && damping_ratio >= 0.0) =>
                        {
                            return bad(
                                "motor.target",
                                format!(
                                    "needs a finite target, hertz > 0 and damping ≥ 0, got \
                                 {target}, {hertz} Hz, {damping_ratio}"
                                ),
                            );
                        }
                        _ => {}
                    }
                }
                if let Some(s) = spring {
                    if !(s.rest.is_finite()
                        && s.hertz.is_finite()
                        && s.hertz > 0.0
                        && s.damping_ratio.is_finite()
                        && s.damping_ratio >= 0.0)
                    {
                        return bad(
                            "spring",
                            format!(
                                "needs a finite rest, hertz > 0 and damping ≥ 0, got {}, {} Hz, {}",
                                s.rest, s.hertz, s.damping_ratio
                            ),
                        );
                    }
                }
                Ok(())
            };
        match &self.kind {
            JointKind::Fixed => Ok(()),
            JointKind::Revolute {
                limits,
                motor,
                spring,
            } => {
                angle("limits", limits)?;
                drive(motor, spring)
            }
            JointKind::Prismatic {
                limits,
                motor,
                spring,
            } => {
                if let Some(l) = limits {
                    if !(l.lower.is_finite() && l.upper.is_finite() && l.lower <= l.upper) {
                        return bad(
                            "limits",
                            format!(
                                "must be finite with lower ≤ upper, got {} … {}",
                                l.lower, l.upper
                            ),
                        );
                    }
                }
                drive(motor, spring)
            }
            JointKind::Spherical { cone, twist } => {
                if let Some(c) = cone {
                    if !(c.is_finite() && *c > 0.0 && *c <= std::f32::consts::PI) {
                        return bad("cone", format!("must be in (0, π], got {c}"));
                    }
                }
                angle("twist", twist)
            }
            JointKind::Distance { min, max, spring } => {
                if !(min.is_finite() && max.is_finite() && *min >= 0.0 && min <= max) {
                    return bad(
                        "limits",
                        format!("distances must be finite with 0 ≤ min ≤ max, got {min} … {max}"),
                    );
                }
                drive(&None, spring)
            }
        }
    }
}
