//! [`SolverBody`]: per-step constants of an awake body inside the solver (its changing
//! state lives in [`super::body_state::BodyState`]).

use glam::{Mat3, Quat, Vec3, Vec3A};

/// [`SolverBody::capped`] bit: the linear speed was clamped to `max_linear_speed`.
pub(crate) const CAPPED_LINEAR: u8 = 1;
/// [`SolverBody::capped`] bit: the spin was clamped to `max_angular_speed`.
pub(crate) const CAPPED_ANGULAR: u8 = 2;

/// Constants of one awake dynamic or kinematic body during a step, and its rotation.
/// Index 0 of the solver array is a dummy for static/sleeping bodies (all zero).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SolverBody {
    /// Rotation since the step began (world frame, applied before the start rotation).
    pub dq: Quat,
    /// World inverse inertia (locked rows/columns zeroed), fixed for the step.
    pub inv_i: Mat3,
    /// Constant linear acceleration (gravity + force / m), m/s².
    pub lin_acc: Vec3A,
    /// Constant angular acceleration (I⁻¹ torque), rad/s².
    pub ang_acc: Vec3A,
    /// Linear damping factor per substep, `1 / (1 + h·c)` for damping `c` (1/s).
    pub lin_damp_factor: f32,
    /// Angular damping factor per substep, `1 / (1 + h·c)`.
    pub ang_damp_factor: f32,
    /// 1 where translation is free, 0 where locked.
    pub lin_mask: Vec3A,
    /// 1 where rotation is free, 0 where locked.
    pub ang_mask: Vec3A,
    /// Orientation at step start.
    pub q0: Quat,
    /// Body-frame inertia (for the free-rotation update).
    pub inertia_local: Mat3,
    /// Body-frame angular velocity matching the world one `omega_world` (for a gyroscopic
    /// body: while no contact or torque changes the spin, substeps reuse it instead of
    /// converting frames, whose rounding drifted the energy of free rotation).
    pub omega_body: Vec3,
    /// The world angular velocity `omega_body` belongs to (NaN when none does).
    pub omega_world: Vec3A,
    /// Which speed caps the step clamped ([`CAPPED_LINEAR`], [`CAPPED_ANGULAR`]).
    pub capped: u8,
    /// Turn by the energy- and momentum-preserving free-rotation update
    /// ([`super::free_rotation`]): anisotropic inertia, no rotation axis locked.
    pub gyro: bool,
}

impl SolverBody {
    /// The static dummy.
    pub const STATIC: Self = Self {
        dq: Quat::IDENTITY,
        inv_i: Mat3::ZERO,
        lin_acc: Vec3A::ZERO,
        ang_acc: Vec3A::ZERO,
        lin_damp_factor: 1.0,
        ang_damp_factor: 1.0,
        lin_mask: Vec3A::ZERO,
        ang_mask: Vec3A::ZERO,
        q0: Quat::IDENTITY,
        inertia_local: Mat3::ZERO,
        omega_body: Vec3::ZERO,
        omega_world: Vec3A::NAN,
        capped: 0,
        gyro: false,
    };
}
