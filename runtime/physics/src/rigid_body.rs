//! [`RigidBody`]: state of one body (pose, velocity, mass, accumulated forces, flags).

use glam::{Mat3, Quat, Vec3};

use crate::body_type::BodyType;
use crate::collider_handle::ColliderHandle;
use crate::locked_axes::LockedAxes;
use crate::mass_properties::MassProperties;
use crate::pose::Pose;

/// Mass (kg) given to a dynamic body whose colliders have no volume and no explicit mass.
pub const FALLBACK_MASS: f32 = 1.0;

/// A rigid body. Create with [`crate::RigidBodyDesc`] and [`crate::PhysicsWorld::insert_body`].
///
/// Setters that change motion wake the body (and, at the next step, its island).
#[derive(Clone, Debug)]
pub struct RigidBody {
    pub(crate) body_type: BodyType,
    pub(crate) pose: Pose,
    pub(crate) linvel: Vec3,
    pub(crate) angvel: Vec3,
    pub(crate) force: Vec3,
    pub(crate) torque: Vec3,
    pub(crate) gravity_scale: f32,
    pub(crate) gravity_enabled: bool,
    pub(crate) linear_damping: f32,
    pub(crate) angular_damping: f32,
    pub(crate) locked: LockedAxes,
    pub(crate) mass_override: Option<MassProperties>,
    pub(crate) mass: MassProperties,
    pub(crate) inv_mass: f32,
    pub(crate) inv_inertia_local: Mat3,
    pub(crate) anisotropic: bool,
    pub(crate) ccd_enabled: bool,
    pub(crate) can_sleep: bool,
    pub(crate) sleeping: bool,
    pub(crate) sleep_timer: f32,
    pub(crate) wake_requested: bool,
    pub(crate) quarantined: bool,
    pub(crate) colliders: Vec<ColliderHandle>,
    pub(crate) user_data: u64,
    pub(crate) grounded: bool,
    pub(crate) last_contact_normal: Option<Vec3>,
    pub(crate) kinematic_target: Option<Pose>,
    /// Index into the solver arrays during a step (0 = the static dummy).
    pub(crate) solver_index: u32,
    /// Sleeping island id (`u32::MAX` when awake).
    pub(crate) island: u32,
    /// Pose at the start of the current step (rollback target for quarantine).
    pub(crate) last_good_pose: Pose,
    /// Body-frame angular velocity of a freely rotating body, and the world angular
    /// velocity and orientation it was taken with: valid while both are unchanged (see
    /// `SolverBody::omega_body`).
    pub(crate) spin_cache: Option<SpinCache>,
    /// Speed caps already reported for this body (`SolverBody::capped` bits).
    pub(crate) caps_reported: u8,
    /// Already named in `StepOutput::far_bodies`.
    pub(crate) far_reported: bool,
    /// Smallest dimension of its colliders, metres ([`crate::shape::Shape::size`];
    /// `f32::MAX` with none): how finely `f32` must place it (see
    /// [`crate::PhysicsSettings::precise_range_for`]).
    pub(crate) size: f32,
}

/// See [`RigidBody::spin_cache`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SpinCache {
    pub world: Vec3,
    pub rotation: Quat,
    pub body: Vec3,
}

impl RigidBody {
    /// Dynamic with CCD on: CCD sweeps its motion and stops it (when the world's
    /// `ccd_enabled` is on too).
    pub(crate) fn swept(&self) -> bool {
        self.ccd_enabled && self.body_type == BodyType::Dynamic
    }

    /// Dynamic, kinematic or static.
    #[must_use]
    pub fn body_type(&self) -> BodyType {
        self.body_type
    }

    /// Pose of the body origin.
    #[must_use]
    pub fn pose(&self) -> Pose {
        self.pose
    }

    /// Position of the body origin, metres.
    #[must_use]
    pub fn translation(&self) -> Vec3 {
        self.pose.translation
    }

    /// Orientation.
    #[must_use]
    pub fn rotation(&self) -> Quat {
        self.pose.rotation
    }

    /// Linear velocity of the centre of mass, m/s.
    #[must_use]
    pub fn linvel(&self) -> Vec3 {
        self.linvel
    }

    /// Angular velocity, rad/s (world axes).
    #[must_use]
    pub fn angvel(&self) -> Vec3 {
        self.angvel
    }

    /// Velocity of a world point attached to the body, m/s.
    #[must_use]
    pub fn velocity_at_point(&self, p: Vec3) -> Vec3 {
        self.linvel + self.angvel.cross(p - self.center_of_mass())
    }

    /// World centre of mass, metres.
    #[must_use]
    pub fn center_of_mass(&self) -> Vec3 {
        self.pose.transform_point(self.mass.local_com)
    }

    /// Mass in kg (0 for non-dynamic bodies).
    #[must_use]
    pub fn mass(&self) -> f32 {
        if self.body_type.is_dynamic() {
            self.mass.mass
        } else {
            0.0
        }
    }

    /// Inverse mass, 1/kg (0 for non-dynamic bodies).
    #[must_use]
    pub fn inv_mass(&self) -> f32 {
        self.inv_mass
    }

    /// Mass properties in the body frame (computed from colliders or set explicitly).
    #[must_use]
    pub fn mass_properties(&self) -> &MassProperties {
        &self.mass
    }

    /// World inertia tensor about the centre of mass, kg·m².
    #[must_use]
    pub fn world_inertia(&self) -> Mat3 {
        let r = Mat3::from_quat(self.pose.rotation);
        r * self.mass.inertia * r.transpose()
    }

    /// World inverse inertia tensor (locked rotation axes zeroed), 1/(kg·m²).
    #[must_use]
    pub fn world_inv_inertia(&self) -> Mat3 {
        let r = Mat3::from_quat(self.pose.rotation);
        let m = r * self.inv_inertia_local * r.transpose();
        mask_mat(m, self.locked.rotation_mask())
    }

    /// Sum of user forces applied since the last step, N.
    #[must_use]
    pub fn user_force(&self) -> Vec3 {
        self.force
    }

    /// Sum of user torques applied since the last step, N·m.
    #[must_use]
    pub fn user_torque(&self) -> Vec3 {
        self.torque
    }

    /// Gravity multiplier.
    #[must_use]
    pub fn gravity_scale(&self) -> f32 {
        self.gravity_scale
    }

    /// Whether global gravity applies.
    #[must_use]
    pub fn gravity_enabled(&self) -> bool {
        self.gravity_enabled
    }

    /// Linear damping, 1/s.
    #[must_use]
    pub fn linear_damping(&self) -> f32 {
        self.linear_damping
    }

    /// Angular damping, 1/s.
    #[must_use]
    pub fn angular_damping(&self) -> f32 {
        self.angular_damping
    }

    /// Locked axes.
    #[must_use]
    pub fn locked_axes(&self) -> LockedAxes {
        self.locked
    }

    /// Whether continuous collision detection runs for this body (if also enabled globally).
    #[must_use]
    pub fn ccd_enabled(&self) -> bool {
        self.ccd_enabled
    }

    /// Whether the body is asleep.
    #[must_use]
    pub fn is_sleeping(&self) -> bool {
        self.sleeping
    }

    /// Whether the body was quarantined after its state became non-finite.
    #[must_use]
    pub fn is_quarantined(&self) -> bool {
        self.quarantined
    }

    /// True when a contact during the last step pushed the body up (normal y above
    /// `PhysicsSettings::grounded_min_normal_y`).
    #[must_use]
    pub fn is_grounded(&self) -> bool {
        self.grounded
    }

    /// Normal (pointing toward this body) of the deepest contact of the last step.
    #[must_use]
    pub fn last_contact_normal(&self) -> Option<Vec3> {
        self.last_contact_normal
    }

    /// Colliders attached to the body.
    #[must_use]
    pub fn colliders(&self) -> &[ColliderHandle] {
        &self.colliders
    }

    /// User payload.
    #[must_use]
    pub fn user_data(&self) -> u64 {
        self.user_data
    }

    /// Sets the payload.
    pub fn set_user_data(&mut self, data: u64) {
        self.user_data = data;
    }

    /// Wakes the body (and its island at the next step).
    pub fn wake_up(&mut self) {
        if self.body_type != BodyType::Static {
            self.sleeping = false;
            self.sleep_timer = 0.0;
            self.wake_requested = true;
        }
    }

    /// Puts the body to sleep now (velocities zeroed).
    pub fn sleep(&mut self) {
        if self.body_type != BodyType::Static {
            self.sleeping = true;
            self.linvel = Vec3::ZERO;
            self.angvel = Vec3::ZERO;
        }
    }

    /// Teleports the body origin. Wakes the body.
    pub fn set_translation(&mut self, t: Vec3) {
        self.pose.translation = t;
        self.wake_up();
        // Static bodies do not wake, but their bounds must follow the teleport.
        self.wake_requested = true;
    }

    /// Sets the orientation (normalised). Wakes the body.
    pub fn set_rotation(&mut self, q: Quat) {
        self.pose.rotation = q.normalize();
        self.wake_up();
        // Static bodies do not wake, but their bounds must follow the teleport.
        self.wake_requested = true;
    }

    /// Sets the whole pose. Wakes the body.
    pub fn set_pose(&mut self, pose: Pose) {
        self.pose = Pose::new(pose.translation, pose.rotation.normalize());
        self.wake_up();
        // Static bodies do not wake, but their bounds must follow the teleport.
        self.wake_requested = true;
    }

    /// Sets the linear velocity (ignored for static bodies). Wakes the body.
    pub fn set_linvel(&mut self, v: Vec3) {
        if self.body_type != BodyType::Static {
            self.linvel = v;
            self.wake_up();
        }
    }

    /// Sets the angular velocity (ignored for static bodies). Wakes the body.
    pub fn set_angvel(&mut self, w: Vec3) {
        if self.body_type != BodyType::Static {
            self.angvel = w;
            self.wake_up();
        }
    }

    /// For kinematic bodies: the pose to reach at the end of the next step. The step
    /// derives the velocity from it, so touching dynamic bodies are pushed and carried.
    pub fn set_next_kinematic_pose(&mut self, pose: Pose) {
        if self.body_type == BodyType::Kinematic {
            self.kinematic_target = Some(pose);
            self.wake_up();
        }
    }

    /// Adds a force (N) at the centre of mass until the end of the next step.
    pub fn add_force(&mut self, f: Vec3) {
        if self.body_type.is_dynamic() {
            self.force += f;
            self.wake_up();
        }
    }

    /// Adds a torque (N·m) until the end of the next step.
    pub fn add_torque(&mut self, t: Vec3) {
        if self.body_type.is_dynamic() {
            self.torque += t;
            self.wake_up();
        }
    }

    /// Adds a force (N) at a world point (adds the matching torque).
    pub fn add_force_at_point(&mut self, f: Vec3, p: Vec3) {
        if self.body_type.is_dynamic() {
            self.force += f;
            self.torque += (p - self.center_of_mass()).cross(f);
            self.wake_up();
        }
    }

    /// Clears accumulated user force and torque.
    pub fn reset_forces(&mut self) {
        self.force = Vec3::ZERO;
        self.torque = Vec3::ZERO;
    }

    /// Applies a linear impulse (N·s) at the centre of mass now.
    pub fn apply_impulse(&mut self, j: Vec3) {
        if self.body_type.is_dynamic() {
            self.linvel += j * self.inv_mass * self.locked.translation_mask();
            self.wake_up();
        }
    }

    /// Applies an angular impulse (N·m·s) now.
    pub fn apply_torque_impulse(&mut self, j: Vec3) {
        if self.body_type.is_dynamic() {
            self.angvel += self.world_inv_inertia() * j;
            self.wake_up();
        }
    }

    /// Applies an impulse (N·s) at a world point now.
    pub fn apply_impulse_at_point(&mut self, j: Vec3, p: Vec3) {
        let torque = (p - self.center_of_mass()).cross(j);
        self.apply_impulse(j);
        self.apply_torque_impulse(torque);
    }

    /// Sets the gravity multiplier. Wakes the body.
    pub fn set_gravity_scale(&mut self, s: f32) {
        self.gravity_scale = s;
        self.wake_up();
    }

    /// Turns global gravity on or off for this body. Wakes the body.
    pub fn set_gravity_enabled(&mut self, on: bool) {
        self.gravity_enabled = on;
        self.wake_up();
    }

    /// Sets linear damping (1/s, `>= 0`).
    pub fn set_linear_damping(&mut self, d: f32) {
        self.linear_damping = d.max(0.0);
    }

    /// Sets angular damping (1/s, `>= 0`).
    pub fn set_angular_damping(&mut self, d: f32) {
        self.angular_damping = d.max(0.0);
    }

    /// Sets the locked axes. Wakes the body.
    pub fn set_locked_axes(&mut self, locked: LockedAxes) {
        self.locked = locked;
        self.wake_up();
    }

    /// Turns CCD on or off for this body.
    pub fn set_ccd_enabled(&mut self, on: bool) {
        self.ccd_enabled = on;
    }

    /// Overrides the mass properties, at once. `None` goes back to the colliders' mass the
    /// next time the world recomputes it (when a collider is added or removed).
    pub fn set_mass_properties(&mut self, mp: Option<MassProperties>) {
        self.mass_override = mp;
        // An explicit mass applies at once; `None` returns to the colliders' mass the next
        // time the world recomputes it (a collider is added or removed).
        if let Some(mp) = mp {
            self.mass = mp;
            if self.body_type != BodyType::Dynamic {
                self.mass.local_com = Vec3::ZERO;
            }
            self.update_inverse_mass();
        }
        self.wake_up();
    }

    /// Recomputes inverse mass and inertia from `mass` (internal).
    pub(crate) fn update_inverse_mass(&mut self) {
        if !self.body_type.is_dynamic() {
            self.inv_mass = 0.0;
            self.inv_inertia_local = Mat3::ZERO;
            self.anisotropic = false;
            return;
        }
        if self.mass.mass.is_nan() || self.mass.mass <= 0.0 || !self.mass.is_finite() {
            self.mass = MassProperties::new(
                self.mass.local_com,
                FALLBACK_MASS,
                Vec3::splat(FALLBACK_MASS * 0.1),
            );
        }
        self.inv_mass = 1.0 / self.mass.mass;
        let i = self.mass.inertia;
        let det = i.determinant();
        self.inv_inertia_local = if det.abs() > 1e-30 && det.is_finite() {
            i.inverse()
        } else {
            // Degenerate tensor (e.g. a zero-size axis): invert the diagonal only.
            let d = Vec3::new(i.x_axis.x, i.y_axis.y, i.z_axis.z);
            Mat3::from_diagonal(Vec3::select(d.cmpgt(Vec3::ZERO), d.recip(), Vec3::ZERO))
        };
        let d = Vec3::new(i.x_axis.x, i.y_axis.y, i.z_axis.z);
        let off = i.x_axis.y.abs() + i.x_axis.z.abs() + i.y_axis.z.abs();
        self.anisotropic = (d.max_element() - d.min_element()) > 1e-6 * d.max_element()
            || off > 1e-6 * d.max_element();
    }
}

/// Zeroes rows and columns of `m` where `mask` is 0.
#[inline]
#[must_use]
pub(crate) fn mask_mat(m: Mat3, mask: Vec3) -> Mat3 {
    if mask == Vec3::ONE {
        return m;
    }
    Mat3::from_cols(
        m.x_axis * mask * mask.x,
        m.y_axis * mask * mask.y,
        m.z_axis * mask * mask.z,
    )
}
