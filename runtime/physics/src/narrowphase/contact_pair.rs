//! [`ContactPair`]: persistent contact state of two colliders.

use crate::body_handle::BodyHandle;
use crate::collider_handle::ColliderHandle;

use super::contact_manifold::ContactManifold;

/// Two colliders whose enlarged bounds overlap, with their manifolds (usually one; one per
/// triangle against meshes).
#[derive(Clone, Debug, PartialEq)]
pub struct ContactPair {
    /// First collider (normals point away from it).
    pub collider_a: ColliderHandle,
    /// Second collider.
    pub collider_b: ColliderHandle,
    /// Body of `collider_a`.
    pub body_a: BodyHandle,
    /// Body of `collider_b`.
    pub body_b: BodyHandle,
    /// Manifolds, including speculative points (positive separation).
    pub manifolds: Vec<ContactManifold>,
    /// True while the pair is in contact: set when a point overlaps (separation `<= 0`) or
    /// carried a normal impulse during the step; cleared when no point carries impulse and
    /// all separations exceed the linear slop.
    pub touching: bool,
    /// One of the colliders is a sensor: the pair reports overlap and is not solved.
    pub sensor: bool,
    /// Combined restitution.
    pub restitution: f32,
    /// Combined static friction.
    pub static_friction: f32,
    /// Combined dynamic friction.
    pub dynamic_friction: f32,
    /// Smallest separation of the last update, metres.
    pub(crate) min_separation: f32,
    /// Manifolds were regenerated (or refreshed) this step.
    pub(crate) updated: bool,
    /// Whether a point of the pair pushed (`max_normal_impulse > 0`), noted by the solve
    /// stage while it writes the impulses back (`None` when the pair was not solved this
    /// step), so that touch tracking need not walk the points again.
    pub(crate) solved_pushing: Option<bool>,
    /// The bodies' poses when the manifolds were last generated; `None` until the first
    /// generation.
    pub(crate) generated_at: Option<Generation>,
    /// Two balls: one point on the line of centres, rewritten every step, which the solver's
    /// linearised separation follows exactly within the step (no lever arm turns it), so
    /// its contact may stiffen further with load (see `Softness::max_ball_load_hertz`).
    pub(crate) ball_ball: bool,
    /// Smallest dimension of the smaller collider, metres (`f32::MAX` when neither is
    /// finite): the scale of the penetration the pair's contact may settle at.
    pub(crate) size: f32,
    /// The larger absolute world coordinate of the two bodies at the last update, m: the
    /// scale of the rounding of their separation (`solver::contact_constraint::
    /// touching_distance`).
    pub(crate) reach: f32,
    /// The pair was named in `StepOutput::overloaded_contacts` (once per pair).
    pub(crate) overload_reported: bool,
    /// The step (`NarrowPhase::updates`) its own load last overloaded it, and how many
    /// steps running it had then: a pair is named only once that reaches
    /// `OVERLOAD_SUSTAIN_STEPS`, so that an impact, whose impulse is the load of one step
    /// only, and a body settling into its place are not.
    pub(crate) overloaded_at: Option<u32>,
    pub(crate) overloaded_steps: u16,
    /// Largest per-substep normal impulse a manifold of the pair carried recently, N·s,
    /// decaying with half-life `solver::softness::LOAD_MEMORY_HALF_LIFE`: the load its
    /// contact stiffens for (a bounce that unloads it for a step keeps it stiff).
    pub(crate) load_memory: f32,
    /// Steps the pair has been solved (saturating): a face younger than
    /// `pipeline::solve_stage::NEW_FACE_STEPS` carries at least the column on it.
    pub(crate) solved_steps: u16,
    /// Steps running that the pair's contact was a column face (`ContactConstraint::column`;
    /// 0 when it was not last step): a column face settled for
    /// `solver::contact_batch::COLUMN_SETTLE_STEPS`, or one since its first step, may
    /// stiffen past the step's cap.
    pub(crate) column_steps: u16,
}

/// Poses a pair's manifolds were generated at, which reuse is measured against.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Generation {
    /// B's body translation in A's body frame.
    pub(crate) translation: glam::Vec3,
    /// B's body rotation in A's body frame.
    pub(crate) rotation: glam::Quat,
    /// A's body rotation (world): the normals stay fixed in world axes while reused, so A
    /// must not have turned far either.
    pub(crate) rotation_a: glam::Quat,
}

impl ContactPair {
    /// Total number of contact points.
    #[must_use]
    pub fn point_count(&self) -> usize {
        self.manifolds.iter().map(|m| m.points.len()).sum()
    }

    /// Both friction coefficients below `solver::LEVEL_MAX_FRICTION`: the pair's faces are
    /// levelled and keep their normal (`narrow_phase::FRICTIONLESS_NORMAL_HOLD_ANGLE`), and a
    /// heavy body on a light one is solved on the true masses
    /// (`heavy_on_light::support_mass_scale`).
    #[inline]
    pub(crate) fn frictionless(&self) -> bool {
        self.static_friction.max(self.dynamic_friction) < crate::solver::LEVEL_MAX_FRICTION
    }

    /// Restitution 1 and no friction: the pair's contacts can do no work (see
    /// `solver::elastic_energy`).
    #[inline]
    pub(crate) fn elastic(&self) -> bool {
        self.restitution >= 1.0 && self.static_friction == 0.0 && self.dynamic_friction == 0.0
    }
}
