//! [`BodyState`]: the part of an awake body that the contact solver reads and writes.

use glam::Vec3A;

/// Velocity and position deltas of one awake body during a step, plus its inverse mass:
/// everything the contact passes touch, packed apart from the rest of [`super::solver_body::SolverBody`]
/// so that the hot loop streams 60 bytes per body instead of ~250.
/// Index 0 is the static dummy (all zero, never written).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct BodyState {
    /// Linear velocity of the centre of mass, m/s.
    pub v: Vec3A,
    /// Angular velocity, rad/s.
    pub w: Vec3A,
    /// Displacement of the centre of mass since the step began, m.
    pub dp: Vec3A,
    /// Accumulated rotation vector since the step began (Σ ω·h), for linearised contact
    /// separation updates.
    pub dtheta: Vec3A,
    /// Inverse mass per world axis (0 on locked axes), 1/kg.
    pub inv_mass: Vec3A,
}

impl BodyState {
    /// The static dummy.
    pub const STATIC: Self = Self {
        v: Vec3A::ZERO,
        w: Vec3A::ZERO,
        dp: Vec3A::ZERO,
        dtheta: Vec3A::ZERO,
        inv_mass: Vec3A::ZERO,
    };
}
