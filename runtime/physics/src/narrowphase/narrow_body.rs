//! [`NarrowBody`]: the part of a body the narrowphase reads for every pair, copied out of
//! the step's awake bodies into one compact array.
//!
//! A pile of 8,000 spheres has 121,000 pairs; each reads both bodies' pose, velocities and
//! flags, which a [`RigidBody`] spreads over several cache lines of a few hundred bytes.
//! Copied once per step per awake body (in arena order, a sequential pass), the pair loop
//! reads 80 bytes per body from an array that stays in cache.

use glam::{Quat, Vec3};

use crate::body_type::BodyType;
use crate::rigid_body::RigidBody;

use super::narrow_phase::is_active;

/// What the narrowphase needs of one body this step.
///
/// Laid out in order (`repr(C)`) with a zero after the last vector: the compiler loads a
/// `Vec3` as four lanes, and flag bytes read as a float are subnormal, which made every
/// multiply on that vector take a microcode assist (the pyramid's narrowphase ran 5× slower).
#[derive(Clone, Copy, Debug, Default)]
#[repr(C)]
pub(crate) struct NarrowBody {
    pub rotation: Quat,
    pub translation: Vec3,
    pub linvel: Vec3,
    pub angvel: Vec3,
    /// Centre of mass in the body's frame.
    pub local_com: Vec3,
    /// Always 0 (see above).
    lane_pad: f32,
    /// Takes part in this step (not static, asleep or quarantined).
    pub active: bool,
    pub quarantined: bool,
    pub ccd_enabled: bool,
    /// Dynamic and asleep: a contact with an awake body wakes it.
    pub sleeping_dynamic: bool,
    /// Moved by the user, not by contacts: its turns are real, never a soft contact's tilt.
    pub kinematic: bool,
}

impl NarrowBody {
    /// The copy of `b`.
    #[inline]
    pub(crate) fn of(b: &RigidBody) -> Self {
        Self {
            rotation: b.pose.rotation,
            translation: b.pose.translation,
            linvel: b.linvel,
            angvel: b.angvel,
            local_com: b.mass.local_com,
            lane_pad: 0.0,
            active: is_active(b),
            quarantined: b.quarantined,
            ccd_enabled: b.ccd_enabled,
            sleeping_dynamic: b.body_type == BodyType::Dynamic && b.sleeping,
            kinematic: b.body_type == BodyType::Kinematic,
        }
    }
}
