//! [`RigidBody`]: makes an entity move under physics.

use abi_stable::StableAbi;
use glam::Vec3;
use serde::{Deserialize, Serialize};

use super::builtin::{finite, FileRefs, HostRefs};
use crate::{Builtin, InvalidValue};

/// How a body moves.
#[repr(u8)]
#[derive(StableAbi, Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum BodyKind {
    /// Moved by forces, gravity and contacts.
    #[default]
    Dynamic,
    /// Moved only by the user (its transform or velocity); pushes dynamic bodies, takes no
    /// impulse itself.
    Kinematic,
    /// Never moves.
    Static,
}

/// Per-axis locks (bit flags): a locked axis neither translates nor rotates.
#[repr(transparent)]
#[derive(StableAbi, Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(transparent)]
pub struct LockedAxes(pub u8);

impl LockedAxes {
    /// Nothing locked.
    pub const NONE: Self = Self(0);
    /// No motion along X.
    pub const TRANSLATION_X: Self = Self(1);
    /// No motion along Y.
    pub const TRANSLATION_Y: Self = Self(2);
    /// No motion along Z.
    pub const TRANSLATION_Z: Self = Self(4);
    /// No rotation about X.
    pub const ROTATION_X: Self = Self(8);
    /// No rotation about Y.
    pub const ROTATION_Y: Self = Self(16);
    /// No rotation about Z.
    pub const ROTATION_Z: Self = Self(32);
    /// No rotation at all.
    pub const ALL_ROTATIONS: Self = Self(56);

    /// Both sets of locks.
    #[must_use]
    pub const fn union(self, other: Self) -> Self {
        Self(self.0 | other.0)
    }
}

/// A rigid body at the entity's [`Transform`](crate::Transform), shaped by its
/// [`Collider`](crate::Collider). The host steps physics in each fixed step and writes the
/// pose back to the transform and the state fields below back to this component.
///
/// Writing the transform teleports the body; writing the velocities sets them.
#[repr(C)]
#[derive(StableAbi, Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RigidBody {
    /// Dynamic, kinematic or static.
    pub kind: BodyKind,
    /// Linear velocity, m/s.
    #[sabi(unsafe_opaque_field)]
    pub linear_velocity: Vec3,
    /// Angular velocity, rad/s (world axes).
    #[sabi(unsafe_opaque_field)]
    pub angular_velocity: Vec3,
    /// Mass in kg; 0 computes mass and inertia from the colliders' densities.
    pub mass: f32,
    /// Multiplier on gravity (0 = no gravity, 1 = normal).
    pub gravity_scale: f32,
    /// Linear damping, 1/s.
    pub linear_damping: f32,
    /// Angular damping, 1/s.
    pub angular_damping: f32,
    /// Axis locks.
    pub locked_axes: LockedAxes,
    /// Continuous collision detection: stops a fast body tunnelling through thin walls.
    pub ccd: bool,
    /// Whether the body may fall asleep when it comes to rest (a sleeping body costs nothing).
    pub can_sleep: bool,
    /// Written by the host: the body is asleep.
    pub sleeping: bool,
    /// Written by the host: the body rests on something below it.
    pub grounded: bool,
    /// Written by the host: normal of its last contact (zero when none).
    #[sabi(unsafe_opaque_field)]
    pub contact_normal: Vec3,
}

impl Default for RigidBody {
    fn default() -> Self {
        Self::dynamic()
    }
}

impl RigidBody {
    /// A dynamic body at rest, mass from density, normal gravity, able to sleep.
    pub const fn dynamic() -> Self {
        Self {
            kind: BodyKind::Dynamic,
            linear_velocity: Vec3::ZERO,
            angular_velocity: Vec3::ZERO,
            mass: 0.0,
            gravity_scale: 1.0,
            linear_damping: 0.0,
            angular_damping: 0.0,
            locked_axes: LockedAxes::NONE,
            ccd: false,
            can_sleep: true,
            sleeping: false,
            grounded: false,
            contact_normal: Vec3::ZERO,
        }
    }

    /// A kinematic body.
    pub const fn kinematic() -> Self {
        let mut body = Self::dynamic();
        body.kind = BodyKind::Kinematic;
        body
    }

    /// A static body.
    pub const fn fixed() -> Self {
        let mut body = Self::dynamic();
        body.kind = BodyKind::Static;
        body
    }

    /// Returns this body moving at `velocity` m/s.
    #[must_use]
    pub const fn with_velocity(mut self, velocity: Vec3) -> Self {
        self.linear_velocity = velocity;
        self
    }

    /// Returns this body with `mass` kg.
    #[must_use]
    pub const fn with_mass(mut self, mass: f32) -> Self {
        self.mass = mass;
        self
    }

    /// Returns this body with continuous collision detection on or off.
    #[must_use]
    pub const fn with_ccd(mut self, ccd: bool) -> Self {
        self.ccd = ccd;
        self
    }

    /// Returns this body with `locks`.
    #[must_use]
    pub const fn with_locked_axes(mut self, locks: LockedAxes) -> Self {
        self.locked_axes = locks;
        self
    }
}

impl Builtin for RigidBody {
    const NAME: &'static str = "RigidBody";
    type File = RigidBody;

    fn tool_default() -> Option<Self> {
        Some(RigidBody::default())
    }

    fn validate(&self, _refs: &dyn HostRefs) -> Result<(), InvalidValue> {
        finite("linear_velocity", &self.linear_velocity.to_array())?;
        finite("angular_velocity", &self.angular_velocity.to_array())?;
        finite("mass", &[self.mass])?;
        finite("gravity_scale", &[self.gravity_scale])?;
        finite("linear_damping", &[self.linear_damping])?;
        finite("angular_damping", &[self.angular_damping])?;
        if self.mass < 0.0 {
            return Err(InvalidValue::invalid(
                "mass",
                format!(
                    "must be ≥ 0 kg (0: from the colliders' densities), got {}",
                    self.mass
                ),
            ));
        }
        Ok(())
    }

    fn to_file(&self, _refs: &dyn HostRefs) -> RigidBody {
        *self
    }

    fn from_file(file: RigidBody, _refs: &mut dyn FileRefs) -> Result<Self, InvalidValue> {
        Ok(file)
    }
}
