//! [`RigidBodyDesc`]: builder for rigid bodies.

use glam::{Quat, Vec3};

use crate::body_type::BodyType;
use crate::locked_axes::LockedAxes;
use crate::mass_properties::MassProperties;
use crate::pose::Pose;
use crate::rigid_body::RigidBody;

/// Builder for a [`RigidBody`]; pass to [`crate::PhysicsWorld::insert_body`].
///
/// ```
/// use onyx_physics::{RigidBodyDesc, glam::Vec3};
/// let desc = RigidBodyDesc::dynamic().translation(Vec3::new(0.0, 2.0, 0.0)).linear_damping(0.1);
/// ```
#[derive(Clone, Debug)]
#[must_use]
pub struct RigidBodyDesc {
    body_type: BodyType,
    pose: Pose,
    linvel: Vec3,
    angvel: Vec3,
    gravity_scale: f32,
    gravity_enabled: bool,
    linear_damping: f32,
    angular_damping: f32,
    locked: LockedAxes,
    mass: Option<MassProperties>,
    ccd_enabled: bool,
    can_sleep: bool,
    sleeping: bool,
    user_data: u64,
}

impl RigidBodyDesc {
    fn new(body_type: BodyType) -> Self {
        Self {
            body_type,
            pose: Pose::IDENTITY,
            linvel: Vec3::ZERO,
            angvel: Vec3::ZERO,
            gravity_scale: 1.0,
            gravity_enabled: true,
            linear_damping: 0.0,
            angular_damping: 0.0,
            locked: LockedAxes::NONE,
            mass: None,
            ccd_enabled: false,
            can_sleep: true,
            sleeping: false,
            user_data: 0,
        }
    }

    /// A body moved by forces and contacts.
    pub fn dynamic() -> Self {
        Self::new(BodyType::Dynamic)
    }

    /// A body moved by the user; pushes dynamic bodies, takes no impulse.
    pub fn kinematic() -> Self {
        Self::new(BodyType::Kinematic)
    }

    /// A body that never moves (named `fixed` because `static` is a keyword).
    pub fn fixed() -> Self {
        Self::new(BodyType::Static)
    }

    /// Initial position of the body origin, metres.
    pub fn translation(mut self, t: Vec3) -> Self {
        self.pose.translation = t;
        self
    }

    /// Initial orientation.
    pub fn rotation(mut self, q: Quat) -> Self {
        self.pose.rotation = q.normalize();
        self
    }

    /// Initial pose.
    pub fn pose(mut self, pose: Pose) -> Self {
        self.pose = pose;
        self
    }

    /// Initial linear velocity, m/s.
    pub fn linvel(mut self, v: Vec3) -> Self {
        self.linvel = v;
        self
    }

    /// Initial angular velocity, rad/s.
    pub fn angvel(mut self, w: Vec3) -> Self {
        self.angvel = w;
        self
    }

    /// Gravity multiplier (default 1).
    pub fn gravity_scale(mut self, s: f32) -> Self {
        self.gravity_scale = s;
        self
    }

    /// Whether global gravity applies (default true).
    pub fn gravity_enabled(mut self, on: bool) -> Self {
        self.gravity_enabled = on;
        self
    }

    /// Linear damping, 1/s (default 0): `v *= 1 / (1 + h * d)` per substep.
    pub fn linear_damping(mut self, d: f32) -> Self {
        self.linear_damping = d.max(0.0);
        self
    }

    /// Angular damping, 1/s (default 0).
    pub fn angular_damping(mut self, d: f32) -> Self {
        self.angular_damping = d.max(0.0);
        self
    }

    /// Locked axes (default none).
    pub fn locked_axes(mut self, l: LockedAxes) -> Self {
        self.locked = l;
        self
    }

    /// Lock all rotations (e.g. a character capsule).
    pub fn lock_rotations(mut self) -> Self {
        self.locked = self.locked | LockedAxes::ALL_ROTATIONS;
        self
    }

    /// Explicit mass properties instead of ones computed from collider densities.
    pub fn mass_properties(mut self, mp: MassProperties) -> Self {
        self.mass = Some(mp);
        self
    }

    /// Continuous collision detection for this fast body (default off).
    pub fn ccd_enabled(mut self, on: bool) -> Self {
        self.ccd_enabled = on;
        self
    }

    /// Whether the body may fall asleep (default true).
    pub fn can_sleep(mut self, on: bool) -> Self {
        self.can_sleep = on;
        self
    }

    /// Start asleep (default false).
    pub fn sleeping(mut self, on: bool) -> Self {
        self.sleeping = on;
        self
    }

    /// User payload.
    pub fn user_data(mut self, d: u64) -> Self {
        self.user_data = d;
        self
    }

    /// Builds the body (mass is filled in once colliders are attached).
    pub(crate) fn build(&self) -> RigidBody {
        let mut b = RigidBody {
            body_type: self.body_type,
            pose: self.pose,
            linvel: if self.body_type == BodyType::Static {
                Vec3::ZERO
            } else {
                self.linvel
            },
            angvel: if self.body_type == BodyType::Static {
                Vec3::ZERO
            } else {
                self.angvel
            },
            force: Vec3::ZERO,
            torque: Vec3::ZERO,
            gravity_scale: self.gravity_scale,
            gravity_enabled: self.gravity_enabled,
            linear_damping: self.linear_damping,
            angular_damping: self.angular_damping,
            locked: self.locked,
            mass_override: self.mass,
            mass: self.mass.unwrap_or_default(),
            inv_mass: 0.0,
            inv_inertia_local: glam::Mat3::ZERO,
            anisotropic: false,
            ccd_enabled: self.ccd_enabled,
            can_sleep: self.can_sleep,
            sleeping: self.sleeping && self.body_type != BodyType::Static,
            sleep_timer: 0.0,
            wake_requested: false,
            quarantined: false,
            colliders: Vec::new(),
            user_data: self.user_data,
            grounded: false,
            last_contact_normal: None,
            kinematic_target: None,
            solver_index: 0,
            island: u32::MAX,
            last_good_pose: self.pose,
            spin_cache: None,
            caps_reported: 0,
            far_reported: false,
            size: f32::MAX,
        };
        b.update_inverse_mass();
        b
    }
}
