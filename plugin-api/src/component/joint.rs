//! [`Joint`]: holds this entity's rigid body to another body (or to the world).

use abi_stable::StableAbi;
use serde::{Deserialize, Serialize};

use super::builtin::{finite, FileRefs, HostRefs};
use crate::{Builtin, Entity, InvalidValue};

/// What the joint is attached to on its other side.
#[repr(C, u8)]
#[derive(StableAbi, Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum JointTarget {
    /// A fixed point of the world: `other_anchor` is a world point.
    #[default]
    World,
    /// Another entity's rigid body: `other_anchor` is in that entity's frame.
    Body(Entity),
}

/// Which motions a joint removes. Angles are radians, lengths metres.
#[repr(C, u8)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum JointKind {
    /// A weld: no relative motion.
    Fixed,
    /// A hinge about `axis`; its coordinate is the angle turned since the joint was made.
    Revolute,
    /// A slider along `axis`; its coordinate is the translation along it since the joint
    /// was made.
    Prismatic,
    /// A ball joint; the swing of `axis` away from its start may be bounded by `cone`
    /// (radians; 0: no bound), the twist about it by the limits.
    Spherical {
        /// Largest swing, radians (0: none).
        cone: f32,
    },
    /// The anchors stay between `min` and `max` metres apart: a rod when equal, a rope
    /// from `min = 0`. A spring acts toward its rest length within those bounds.
    Distance {
        /// Shortest distance, m.
        min: f32,
        /// Longest distance, m.
        max: f32,
    },
}

/// A drive on the joint's free coordinate (hinge angle or slider translation).
#[repr(C, u8)]
#[derive(StableAbi, Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub enum JointMotor {
    /// No motor.
    #[default]
    Off,
    /// Drives the coordinate's rate to `speed` (rad/s or m/s) with at most `max_force`.
    Velocity {
        /// Target speed.
        speed: f32,
        /// Largest torque (N·m, hinge) or force (N, slider).
        max_force: f32,
    },
    /// A servo: drives the coordinate to `target` like a spring of `hertz` and
    /// `damping_ratio`, with at most `max_force`.
    Position {
        /// Target angle (rad) or translation (m).
        target: f32,
        /// Stiffness, Hz.
        hertz: f32,
        /// Damping ratio (1: critical).
        damping_ratio: f32,
        /// Largest torque or force.
        max_force: f32,
    },
}

/// Joins this entity's rigid body to another body or to the world.
///
/// ```no_run
/// # use onyx_plugin_api::*;
/// # fn demo(ctx: &mut Ctx, frame: Entity, door: Entity) -> Result<(), CtxError> {
/// // A door hinged on its left edge (0.5 m from its centre) to the frame, opening 0…100°.
/// ctx.set(door, Joint::revolute(JointTarget::Body(frame), [0.0, 1.0, 0.0])
///     .with_anchors([-0.5, 0.0, 0.0], [0.5, 0.0, 0.0])
///     .with_limits(0.0, 100f32.to_radians()))?;
/// # Ok(()) }
/// ```
///
/// The joint is made when the component is written, at the bodies' poses then: a hinge's or
/// slider's coordinate is 0 there, and the other side's axis is `axis` as it lies in the
/// world at that moment. `anchor` is in this entity's frame; `other_anchor` in the other
/// entity's frame (a world point for [`JointTarget::World`]). Writing the component again
/// makes the joint afresh. The two bodies stop colliding with each other unless
/// `collide_connected`. A joint whose force passes `break_force` (or torque `break_torque`;
/// 0: never) breaks: the host sets `broken` and logs it once.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Joint {
    /// What it removes.
    pub kind: JointKind,
    /// The other side.
    pub other: JointTarget,
    /// The anchor on this entity, its local frame, m.
    pub anchor: [f32; 3],
    /// The anchor on the other side (its local frame; a world point for the world), m.
    pub other_anchor: [f32; 3],
    /// The hinge or slider axis, or the ball joint's swing axis, in this entity's frame.
    pub axis: [f32; 3],
    /// Whether `lower`/`upper` bound the coordinate (hinge angle, slider translation, ball
    /// twist).
    pub limits: bool,
    /// Lowest coordinate (rad or m).
    pub lower: f32,
    /// Highest coordinate (rad or m).
    pub upper: f32,
    /// A motor on a hinge or slider.
    pub motor: JointMotor,
    /// Spring stiffness toward `spring_rest`, Hz (0: no spring), on a hinge, slider or
    /// distance joint.
    pub spring_hertz: f32,
    /// Spring damping ratio.
    pub spring_damping_ratio: f32,
    /// Where the spring rests (rad or m).
    pub spring_rest: f32,
    /// Force past which it breaks, N (0: never).
    pub break_force: f32,
    /// Torque past which it breaks, N·m (0: never).
    pub break_torque: f32,
    /// Whether the joined bodies still collide with each other.
    pub collide_connected: bool,
    /// Set by the host when the joint broke.
    pub broken: bool,
}

impl Joint {
    /// A joint of `kind` to `other`, anchors at the origins, axis `axis`.
    pub const fn new(kind: JointKind, other: JointTarget, axis: [f32; 3]) -> Self {
        Self {
            kind,
            other,
            anchor: [0.0; 3],
            other_anchor: [0.0; 3],
            axis,
            limits: false,
            lower: 0.0,
            upper: 0.0,
            motor: JointMotor::Off,
            spring_hertz: 0.0,
            spring_damping_ratio: 0.0,
            spring_rest: 0.0,
            break_force: 0.0,
            break_torque: 0.0,
            collide_connected: false,
            broken: false,
        }
    }

    /// A weld.
    pub const fn fixed(other: JointTarget) -> Self {
        Self::new(JointKind::Fixed, other, [1.0, 0.0, 0.0])
    }

    /// A hinge about `axis` (this entity's frame).
    pub const fn revolute(other: JointTarget, axis: [f32; 3]) -> Self {
        Self::new(JointKind::Revolute, other, axis)
    }

    /// A slider along `axis` (this entity's frame).
    pub const fn prismatic(other: JointTarget, axis: [f32; 3]) -> Self {
        Self::new(JointKind::Prismatic, other, axis)
    }

    /// A ball joint.
    pub const fn spherical(other: JointTarget) -> Self {
        Self::new(JointKind::Spherical { cone: 0.0 }, other, [1.0, 0.0, 0.0])
    }

    /// Anchors between `min` and `max` metres apart.
    pub const fn distance(other: JointTarget, min: f32, max: f32) -> Self {
        Self::new(JointKind::Distance { min, max }, other, [1.0, 0.0, 0.0])
    }

    /// With these anchors: on this entity, and on the other side.
    #[must_use]
    pub const fn with_anchors(mut self, anchor: [f32; 3], other_anchor: [f32; 3]) -> Self {
        self.anchor = anchor;
        self.other_anchor = other_anchor;
        self
    }

    /// With limits on the coordinate.
    #[must_use]
    pub const fn with_limits(mut self, lower: f32, upper: f32) -> Self {
        self.limits = true;
        self.lower = lower;
        self.upper = upper;
        self
    }

    /// With a motor.
    #[must_use]
    pub const fn with_motor(mut self, motor: JointMotor) -> Self {
        self.motor = motor;
        self
    }

    /// With a spring toward `rest`.
    #[must_use]
    pub const fn with_spring(mut self, rest: f32, hertz: f32, damping_ratio: f32) -> Self {
        self.spring_rest = rest;
        self.spring_hertz = hertz;
        self.spring_damping_ratio = damping_ratio;
        self
    }

    /// Breaking past `force` newtons or `torque` newton-metres (0: never).
    #[must_use]
    pub const fn with_break(mut self, force: f32, torque: f32) -> Self {
        self.break_force = force;
        self.break_torque = torque;
        self
    }
}

fn not_negative(field: &'static str, value: f32) -> Result<(), InvalidValue> {
    finite(field, &[value])?;
    if value >= 0.0 {
        Ok(())
    } else {
        Err(InvalidValue::invalid(
            field,
            format!("must be ≥ 0, got {value}"),
        ))
    }
}

/// A [`Joint`] as scene files write it: the other body by its file-local id.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JointFile {
    /// What it removes.
    pub kind: JointKind,
    /// The other body's file-local id (`id: Some(N)` on its entity); absent: the world.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub other: Option<u64>,
    /// Anchor on this entity, m.
    #[serde(default)]
    pub anchor: [f32; 3],
    /// Anchor on the other side, m.
    #[serde(default)]
    pub other_anchor: [f32; 3],
    /// Axis in this entity's frame.
    #[serde(default = "x_axis")]
    pub axis: [f32; 3],
    /// Coordinate limits (lower, upper).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limits: Option<(f32, f32)>,
    /// A motor.
    #[serde(default)]
    pub motor: JointMotor,
    /// A spring: (rest, hertz, damping ratio).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spring: Option<(f32, f32, f32)>,
    /// Break force, N (0: never).
    #[serde(default)]
    pub break_force: f32,
    /// Break torque, N·m (0: never).
    #[serde(default)]
    pub break_torque: f32,
    /// Whether the joined bodies still collide.
    #[serde(default)]
    pub collide_connected: bool,
    /// Whether it broke.
    #[serde(default)]
    pub broken: bool,
}

fn x_axis() -> [f32; 3] {
    [1.0, 0.0, 0.0]
}

impl Builtin for Joint {
    const NAME: &'static str = "Joint";
    type File = JointFile;

    fn tool_default() -> Option<Self> {
        None
    }

    fn validate(&self, refs: &dyn HostRefs) -> Result<(), InvalidValue> {
        finite("anchor", &self.anchor)?;
        finite("other_anchor", &self.other_anchor)?;
        finite("axis", &self.axis)?;
        if self.axis.iter().map(|a| a * a).sum::<f32>() < 1e-12 {
            return Err(InvalidValue::invalid("axis", "must not be zero"));
        }
        if let JointTarget::Body(other) = self.other {
            if !refs.contains(other) {
                return Err(InvalidValue::invalid(
                    "other",
                    format!("names entity {other}, which does not exist"),
                ));
            }
        }
        match self.kind {
            JointKind::Spherical { cone } => {
                not_negative("kind.cone", cone)?;
                if cone > std::f32::consts::PI {
                    return Err(InvalidValue::invalid(
                        "kind.cone",
                        format!("must be at most π, got {cone}"),
                    ));
                }
            }
            JointKind::Distance { min, max } => {
                not_negative("kind.min", min)?;
                not_negative("kind.max", max)?;
                if min > max {
                    return Err(InvalidValue::invalid(
                        "kind.max",
                        format!("must be ≥ min ({min}), got {max}"),
                    ));
                }
            }
            JointKind::Fixed | JointKind::Revolute | JointKind::Prismatic => {}
        }
        finite("lower", &[self.lower])?;
        finite("upper", &[self.upper])?;
        if self.limits {
            if self.lower > self.upper {
                return Err(InvalidValue::invalid(
                    "upper",
                    format!("must be ≥ lower ({}), got {}", self.lower, self.upper),
                ));
            }
            let angular = matches!(self.kind, JointKind::Revolute | JointKind::Spherical { .. });
            let pi = std::f32::consts::PI;
            if angular && (self.lower < -pi || self.upper > pi) {
                return Err(InvalidValue::invalid(
                    "lower",
                    format!(
                        "angle limits must lie within [−π, π], got {} … {}",
                        self.lower, self.upper
                    ),
                ));
            }
        }
        match self.motor {
            JointMotor::Off => {}
            JointMotor::Velocity { speed, max_force } => {
                finite("motor.speed", &[speed])?;
                not_negative("motor.max_force", max_force)?;
            }
            JointMotor::Position {
                target,
                hertz,
                damping_ratio,
                max_force,
            } => {
                finite("motor.target", &[target])?;
                not_negative("motor.damping_ratio", damping_ratio)?;
                not_negative("motor.max_force", max_force)?;
                finite("motor.hertz", &[hertz])?;
                if hertz <= 0.0 {
                    return Err(InvalidValue::invalid(
                        "motor.hertz",
                        format!("must be > 0 Hz, got {hertz}"),
                    ));
                }
            }
        }
        not_negative("spring_hertz", self.spring_hertz)?;
        not_negative("spring_damping_ratio", self.spring_damping_ratio)?;
        finite("spring_rest", &[self.spring_rest])?;
        not_negative("break_force", self.break_force)?;
        not_negative("break_torque", self.break_torque)
    }

    fn to_file(&self, refs: &dyn HostRefs) -> JointFile {
        JointFile {
            kind: self.kind,
            other: match self.other {
                JointTarget::World => None,
                JointTarget::Body(e) => Some(refs.file_id(e).unwrap_or(e.to_bits())),
            },
            anchor: self.anchor,
            other_anchor: self.other_anchor,
            axis: self.axis,
            limits: self.limits.then_some((self.lower, self.upper)),
            motor: self.motor,
            spring: (self.spring_hertz > 0.0).then_some((
                self.spring_rest,
                self.spring_hertz,
                self.spring_damping_ratio,
            )),
            break_force: self.break_force,
            break_torque: self.break_torque,
            collide_connected: self.collide_connected,
            broken: self.broken,
        }
    }

    fn from_file(file: JointFile, refs: &mut dyn FileRefs) -> Result<Self, InvalidValue> {
        let other = match file.other {
            None => JointTarget::World,
            Some(id) => JointTarget::Body(refs.entity(id).ok_or_else(|| {
                InvalidValue::invalid("other", format!("names id {id}, which no entity has"))
            })?),
        };
        let (limits, (lower, upper)) = match file.limits {
            Some(l) => (true, l),
            None => (false, (0.0, 0.0)),
        };
        let (spring_rest, spring_hertz, spring_damping_ratio) =
            file.spring.unwrap_or((0.0, 0.0, 0.0));
        Ok(Joint {
            kind: file.kind,
            other,
            anchor: file.anchor,
            other_anchor: file.other_anchor,
            axis: file.axis,
            limits,
            lower,
            upper,
            motor: file.motor,
            spring_hertz,
            spring_damping_ratio,
            spring_rest,
            break_force: file.break_force,
            break_torque: file.break_torque,
            collide_connected: file.collide_connected,
            broken: file.broken,
        })
    }
}
