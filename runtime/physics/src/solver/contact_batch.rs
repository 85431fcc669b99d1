//! [`ContactBatch`]: four manifolds solved at once, one per SIMD lane (warm start, the
//! normal and friction rows of [`ContactConstraint`](super::contact_constraint::ContactConstraint), restitution).
//!
//! The rows are those of the scalar formulation documented on [`ContactConstraint`](super::contact_constraint::ContactConstraint),
//! [`NormalBlock`](super::contact_constraint::NormalBlock) and
//! [`FrictionPart`](super::contact_constraint::FrictionPart); here every branch is a lane
//! select. The lanes of one batch never share a body they write ([`super::batching`]), so
//! solving them together gives each manifold exactly what solving it alone would. An empty
//! lane has zero masses and changes nothing.
//!
//! Two layouts ([`ManifoldRows`]): [`PointBatch`] for one-point manifolds (spheres, capsule
//! ends), which carry only the point's rows and friction, and [`FaceBatch`] for manifolds of
//! two to four points, which add the shared normal step and twist friction
//! ([`FaceContact`]). The solver streams every batch once per pass, so a one-point batch
//! does not carry what only faces use (a pile of 8,000 spheres is 30,000 manifolds).
//!
//! Each layout comes in two kinds ([`Levers`]): *angular* batches, which carry every point's
//! and the friction's lever arms ([`AngularRows`]), and *linear* batches ([`NoRotation`])
//! for manifolds between bodies that cannot rotate (every rotation axis locked, or a
//! kinematic or static body that is not spinning). A linear batch has no lever arms to
//! stream, reads and writes linear velocities only and skips every angular term: no work
//! for rotation where rotation is locked.

use glam::Vec3A;

use super::body_state::BodyState;
use super::column_solve::{ColumnFace, ColumnRows, FrictionLevers};
use super::contact_constraint::PreparedManifold;
use super::face_contact::FaceContact;
use super::lanes::{
    gather, gather_deltas, gather_velocities, scatter_linear_velocities, scatter_velocities,
    Velocities, F, LANES, V3,
};

/// Four one-point manifolds.
pub(crate) type PointBatch = ContactBatch<1, PointContact, AngularRows<1>>;
/// Four manifolds of two to four points (unused points inactive).
pub(crate) type FaceBatch = ContactBatch<4, FaceContact, AngularRows<4>>;
/// Four one-point manifolds between bodies that do not rotate.
pub(crate) type LinearPointBatch = ContactBatch<1, PointContact, NoRotation>;
/// Four manifolds of two to four points between bodies that do not rotate.
pub(crate) type LinearFaceBatch = ContactBatch<4, FaceContact, NoRotation>;

/// Lanes of one contact point slot.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PointLanes {
    pub base_separation: F,
    pub normal_impulse: F,
    pub max_normal_impulse: F,
    pub normal_mass: F,
    /// Restitution's target (see `ConstraintPoint::restitution_velocity`): > 0 a rebound
    /// speed, ≤ 0 a held velocity.
    pub restitution_velocity: F,
    /// What the restitution passes added to the point's normal impulse this step (see
    /// [`ContactBatch::apply_restitution`]), N·s.
    pub restitution_impulse: F,
}

impl PointLanes {
    const EMPTY: Self = Self {
        base_separation: F::ZERO,
        normal_impulse: F::ZERO,
        max_normal_impulse: F::ZERO,
        normal_mass: F::ZERO,
        restitution_velocity: F::ZERO,
        restitution_impulse: F::ZERO,
    };
}

/// Lever arms of one point slot: the angular Jacobians `r × n` of A and B, and the same
/// through each body's inverse inertia.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PointLevers {
    pub rn_a: V3,
    pub rn_b: V3,
    pub irn_a: V3,
    pub irn_b: V3,
}

impl PointLevers {
    const EMPTY: Self = Self {
        rn_a: V3::ZERO,
        rn_b: V3::ZERO,
        irn_a: V3::ZERO,
        irn_b: V3::ZERO,
    };
}

/// What rotation adds to a batch of manifolds with `N` point slots: each point's lever arms
/// and the friction's at the manifold centre (`r × t1`, `r × t2`, and through the inverse
/// inertia).
#[derive(Clone, Copy, Debug)]
pub(crate) struct AngularRows<const N: usize> {
    points: [PointLevers; N],
    rt_a: [V3; 2],
    rt_b: [V3; 2],
    irt_a: [V3; 2],
    irt_b: [V3; 2],
}

/// Manifolds whose bodies cannot rotate carry no lever arms.
#[derive(Clone, Copy, Debug)]
pub(crate) struct NoRotation;

/// The lever-arm storage of a batch: [`AngularRows`] or [`NoRotation`].
pub(crate) trait Levers<const N: usize>: Copy + std::fmt::Debug {
    /// Four empty lanes.
    const EMPTY: Self;
    /// The bodies may rotate (angular velocities are read and written).
    const ANGULAR: bool;
    /// The lever arms, or `None` for bodies that cannot rotate (known at compile time, so
    /// every angular term of a linear batch compiles away).
    fn rows(&self) -> Option<&AngularRows<N>>;
    /// The same, to write.
    fn rows_mut(&mut self) -> Option<&mut AngularRows<N>>;
}

impl<const N: usize> Levers<N> for AngularRows<N> {
    const ANGULAR: bool = true;
    const EMPTY: Self = Self {
        points: [PointLevers::EMPTY; N],
        rt_a: [V3::ZERO; 2],
        rt_b: [V3::ZERO; 2],
        irt_a: [V3::ZERO; 2],
        irt_b: [V3::ZERO; 2],
    };
    #[inline(always)]
    fn rows(&self) -> Option<&AngularRows<N>> {
        Some(self)
    }
    #[inline(always)]
    fn rows_mut(&mut self) -> Option<&mut AngularRows<N>> {
        Some(self)
    }
}

impl<const N: usize> Levers<N> for NoRotation {
    const ANGULAR: bool = false;
    const EMPTY: Self = Self;
    #[inline(always)]
    fn rows(&self) -> Option<&AngularRows<N>> {
        None
    }
    #[inline(always)]
    fn rows_mut(&mut self) -> Option<&mut AngularRows<N>> {
        None
    }
}

/// Each point's normal row in one pass: where it is speculative (separated: rigid, may not
/// close the gap by more than it is) and its velocity bias.
pub(crate) struct NormalRows<const N: usize> {
    pub speculative: [F; N],
    pub bias: [F; N],
    /// Soft position correction on (solve phase) or off (relax phase).
    pub use_bias: bool,
}

/// Faces with a friction coefficient below this are levelled (see
/// `FaceContact::level_patch`): friction holds a body on a face tilted by the micro-radians a
/// soft contact tilts under an off-centre load.
pub const LEVEL_MAX_FRICTION: f32 = 1e-3;

/// How much of a levelled face's leak is the patch's mean impulse rather than the point's
/// own. Bounded `(0, 1)`: at 1 the face has no leak at all in tilt, and a frictionless column
/// of 20 boxes at 60 Hz × 4 (10 at 30 Hz × 2), which holds without levelling, rocked and fell
/// after 8 s; from 0.95 down to 0.5 the columns hold and so do the offset stacks of 0 leak.
pub const LEVEL_SHARE: f32 = 0.75;

/// How much of the leak of a face levelled under its load (see
/// [`levelled_for_load`]) is the patch's mean impulse: less than a frictionless face's
/// [`LEVEL_SHARE`], so that a brick resting on two supports that sink unevenly keeps some
/// tilt of its own on each. Bounded `(0, 1)`: over five starts of the 100-row pyramid at
/// 60 Hz × 4, 0.9 on every friction face threw it apart (5–15 m) and 0.15 left it swaying
/// (mean 0.90 m); from 0.3 to 0.6 it slumped 0.71 m.
pub const LOADED_LEVEL_SHARE: f32 = 0.4;

/// Fraction of the critical load ratio (see [`levelled_for_load`]) from which a
/// resting face with friction is levelled. Bounded `(0, ∞)`: at 1 the 100-row pyramid at
/// 60 Hz × 4 still swayed (mean 0.98 m over five starts); levelling every friction face
/// (0) made the 20-row pyramid slump 3–6 cm instead of 2.5 cm.
pub const TILT_LEVEL_FRACTION: f32 = 2.0 / 3.0;

/// Load past which a face is part of a column (see [`column_face`]): it carries more than
/// the body on it.
pub const COLUMN_LOAD_RATIO: f32 = 1.5;

/// `h·ω` of a face's stiffness past which its column is not solved by one iteration (see
/// [`column_face`]). Bounded `(0, 2π]`: the loaded faces of ten 3 cm cubes are at 1.3–2.4 at
/// 60 Hz × 4 and the lowest at 1.13 at 120 Hz × 4 (all fell; at 1.3 the latter still fell
/// after 9.5 s); the budget-stiffened faces of the 100-row pyramid stay below 0.89 at
/// 60 Hz × 4 (and its bricks rest on two faces, so none is a column face).
pub const COLUMN_STIFFNESS: f32 = 1.0;

/// Whether a face that carries `carried` (its load ratio; on a static body no more than its
/// load in weights of the body on it), with a stiffness of `hertz` at substep `h`, is a
/// column face: levelled in tilt ([`LEVEL_SHARE`]) and solved again after the iterations
/// (`solve::COLUMN_PASSES`).
///
/// A face stiffened only as far as its depth budget needs is soft in tilt (`k_θ = W·w/(4β)`
/// for a load `W` on a face `w` wide with a depth budget `β` of it), and the faces of a
/// column are tilt springs in series under the load above them, which tips them further the
/// higher it sits: at 2 % budgets a column of ten equal cubes has no stable equilibrium
/// (the chain's stiffness matrix, faces at the stiffness the step picks), and five are
/// marginal. Levelled, a face is stiff in tilt while as soft in depth; but a column of faces
/// stiff in tilt is a chain the step's one iteration does not converge: the columns fell
/// sooner levelled than not, until the column was solved again. Such faces are the ones
/// the depth budget stiffened past about one radian per substep (small bodies under loads;
/// the caller checks that the budget set the stiffness): larger bodies' faces, and a
/// ground face at its base stiffness, are left as they were (the ground face of a 20-box
/// stack taken for one cost the stack 30 %, and every such face taken for one put the
/// 20-row pyramid's bottom row into columns and cost it 1.8 times as much). The one
/// exception is the base of a column: a face at the base rate under a body a column face
/// rests on (`ColumnSupports::carries_column`, as of the last step). Left out, a column
/// levelled and solved as a whole rocked on it: three 1 cm cubes, every other one 20 %
/// aside with friction, walked 57 % of a cube within 10 s at 60 Hz × 4. A face whose
/// column's chain needs more levelling than the iterations converge is a column face too
/// (see `column_chain::ChainFace::needs_column`).
#[must_use]
#[inline]
pub fn column_face(carried: f32, hertz: f32, h: f32) -> bool {
    carried > COLUMN_LOAD_RATIO && h * 2.0 * std::f32::consts::PI * hertz > COLUMN_STIFFNESS
}

/// Steps running a face must have been a column face before it may stiffen past the step's
/// cap, up to `Softness::max_column_hertz`, unless it has been one since it first touched
/// (a column placed at rest, whose new faces carry the column from their first step:
/// `pipeline::solve_stage::NEW_FACE_STEPS`). Bounded `[1, ∞)`: a face that becomes a column
/// in a pile stiffened at once (0), one start of five of the pile of 20 ragdolls at
/// 60 Hz × 4 exploded to 3837 J/kg (`examples/spread.rs` in the physics bench); at 3 all
/// five rest.
pub const COLUMN_SETTLE_STEPS: u16 = 3;

/// A column face is resting while each point closes or parts slower than its depth budget in
/// a step, or, where that is slower, than its budget in a period of the face's own
/// stiffness but no faster than this fraction of a step of free fall, `g·dt`. A tumbling
/// pile is not a column (taken for one, the 100-row pyramid's collapse at `fast` threw
/// bricks 560 m instead of 120), but a stiff face at rest starts its steps with the soft
/// step's correction velocity (−3.7 mm/s on the static ground face of ten 3 mm cubes at
/// 60 Hz × 4, its whole budget in a step): tested against the budget in a step alone, its
/// flag flickered. Bounded `(0.03, 1]`: at 0.03 ten 3 cm cubes at 30 Hz × 2 fell again;
/// from 0.1 to 1 the columns of `tests/stacking.rs` stand and fall alike. (Capping the
/// budget in a step by it too, not only the period's, flickered the faces of the 20-box
/// stack of 1 m boxes at 30 Hz × 1, which vibrate faster than that: it fell.)
pub const COLUMN_REST_FREE_FALL_FRACTION: f32 = 0.1;

/// Fastest a column face's point may close or part and still be resting (see
/// [`COLUMN_REST_FREE_FALL_FRACTION`]), m/s: for a depth `budget`, a face stiffness of
/// `hertz`, gravity `g` and step `dt`.
#[must_use]
#[inline]
pub fn column_rest_speed(budget: f32, hertz: f32, g: f32, dt: f32) -> f32 {
    let per_step = budget / dt;
    let per_period = budget * 2.0 * std::f32::consts::PI * hertz;
    per_step.max(per_period.min(COLUMN_REST_FREE_FALL_FRACTION * g * dt))
}

/// Whether a face with friction of stiffness `hertz` under bodies of `size` metres is
/// levelled for its load: its `load_ratio` (the contact's load over the weight of its own
/// effective mass) is past [`TILT_LEVEL_FRACTION`] of the ratio at which a soft face stops
/// holding the tilt of the column on it, `ω·√(size / 2g)` (compared squared: this runs for
/// every manifold every step).
///
/// A soft face's points deflect in proportion to their impulses, so it resists tilting like
/// a spring of stiffness `k_θ ≈ m·ω²·w²/4` (width `w`, effective mass `m`), and the load it
/// carries, `W = ratio·m·g`, tips it further the higher its centre of mass sits, `ℓ`
/// (the P-Δ effect of a column). Taken as a column of `ratio` bodies of the face's own size
/// (`w = size`, `ℓ = ratio·size/2`), the face holds the column's tilt while `k_θ > W·ℓ`:
/// `ratio < ω·√(size / 2g)`. Past it a sway grows: the 100-row pyramid, a wall one box deep,
/// leaned out of its plane from its lower rows (rows tilting by up to 1e-2 rad about the
/// row's axis, rapier 5e-4) and slumped 0.68–1.86 m over five starts at 60 Hz × 4 (rapier
/// 0.68 m). Its lower rows now level their faces in part ([`LOADED_LEVEL_SHARE`]). Never
/// without gravity.
#[must_use]
#[inline]
pub fn levelled_for_load(load_ratio: f32, hertz: f32, size: f32, g: f32) -> bool {
    let limit = TILT_LEVEL_FRACTION * 2.0 * std::f32::consts::PI * hertz;
    g > 0.0 && load_ratio > 0.0 && load_ratio * load_ratio * 2.0 * g > limit * limit * size
}

/// The lanes whose face [`ManifoldRows::level_patch`] levelled: their points' rows leak the
/// patch's mean impulse instead of their own.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Leveled {
    /// Lane mask.
    pub lanes: F,
    /// Mean accumulated normal impulse of the patch's points.
    pub mean_impulse: F,
    /// 1 / points per lane.
    pub inv_count: F,
    /// How much of each point's leak is the mean impulse, per lane.
    pub share: F,
}

impl Leveled {
    /// No lane levelled.
    pub const NONE: Self = Self {
        lanes: F::ZERO,
        mean_impulse: F::ZERO,
        inv_count: F::ZERO,
        share: F::ZERO,
    };
}

/// What a manifold layout adds to the rows every manifold has.
pub(crate) trait ManifoldRows: Copy + std::fmt::Debug {
    /// Four empty lanes.
    const EMPTY: Self;
    /// Writes lane `l` from a prepared manifold.
    fn set_lane(&mut self, l: usize, prepared: &PreparedManifold);
    /// Adds its warm-start impulses' angular parts (`wa` is subtracted from body A).
    fn warm_start(&self, wa: &mut V3, wb: &mut V3);
    /// Before the per-point sweep: a step shared by all points.
    fn solve_shared<const N: usize>(
        &self,
        points: &mut [PointLanes; N],
        rows: &NormalRows<N>,
        vn: &mut [F; N],
        applied: &mut [F; N],
    );
    /// After the shared step, before the per-point sweep: which lanes hold a resting
    /// frictionless face whose points leak their mean impulse (see
    /// `FaceContact::level_patch`).
    fn level_patch<const N: usize>(
        &self,
        points: &[PointLanes; N],
        rows: &NormalRows<N>,
    ) -> Leveled;
    /// After point `j` took `imp`: how the later points' normal velocities change.
    fn couple<const N: usize>(&self, j: usize, imp: F, vn: &mut [F; N]);
    /// Friction about the normal, after the friction in the plane.
    fn solve_twist<const N: usize>(
        &mut self,
        points: &[PointLanes; N],
        friction: F,
        normal: V3,
        a: &mut Velocities,
        b: &mut Velocities,
    );
    /// Accumulated twist impulse per lane.
    fn twist_impulse(&self) -> F;
}

/// A one-point manifold: no shared step, no coupling, no lever for twist.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct PointContact;

impl ManifoldRows for PointContact {
    const EMPTY: Self = Self;
    #[inline(always)]
    fn set_lane(&mut self, _: usize, _: &PreparedManifold) {}
    #[inline(always)]
    fn warm_start(&self, _: &mut V3, _: &mut V3) {}
    #[inline(always)]
    fn solve_shared<const N: usize>(
        &self,
        _: &mut [PointLanes; N],
        _: &NormalRows<N>,
        _: &mut [F; N],
        _: &mut [F; N],
    ) {
    }
    #[inline(always)]
    fn level_patch<const N: usize>(&self, _: &[PointLanes; N], _: &NormalRows<N>) -> Leveled {
        Leveled::NONE
    }
    #[inline(always)]
    fn couple<const N: usize>(&self, _: usize, _: F, _: &mut [F; N]) {}
    #[inline(always)]
    fn solve_twist<const N: usize>(
        &mut self,
        _: &[PointLanes; N],
        _: F,
        _: V3,
        _: &mut Velocities,
        _: &mut Velocities,
    ) {
    }
    fn twist_impulse(&self) -> F {
        F::ZERO
    }
}

/// The impulses one manifold ends the step with.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct LaneResult {
    /// Accumulated normal impulse per point (points past the manifold's count are 0), N·s.
    pub normal_impulse: [f32; 4],
    /// Largest single normal impulse of the step per point.
    pub max_normal_impulse: [f32; 4],
    /// Friction impulse along the constraint's two tangents.
    pub tangent_impulse: [f32; 2],
    /// The two tangents.
    pub tangent: [Vec3A; 2],
    /// Twist friction impulse about the normal.
    pub twist_impulse: f32,
    /// Per point: restitution added more impulse than the [`Jitter`] takes: the point's
    /// impulse was an impact's, not a load's (not warm started, not remembered as load).
    /// Warm started, a held floor contact under a ball struck from above pushed the ball
    /// back up the next step and a column of two elastic balls gained 13 % at fast; a
    /// resting contact's small rebounds stay warm started (cleared, a stack of eight boxes
    /// with e = 0.5 fell apart at fast).
    pub impact: [bool; 4],
    /// The contact was a column face (`ContactConstraint::column`).
    pub column: bool,
}

/// Two bodies a contact pushed apart this step (see
/// [`ContactBatch::for_each_pushing_link`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Link {
    /// Solver indices of bodies A and B.
    pub bodies: [u32; 2],
    /// Whether the solver writes A (resp. B): it is dynamic.
    pub writes: [bool; 2],
    /// `ContactConstraint::elastic`.
    pub elastic: bool,
}

/// Four manifolds of at most `N` points as lanes, with the rows of layout `M` and the lever
/// arms `L` (none for manifolds whose bodies do not rotate).
#[derive(Clone, Copy, Debug)]
pub(crate) struct ContactBatch<const N: usize, M: ManifoldRows, L: Levers<N>> {
    /// Index into the step's constraints per lane; `u32::MAX` for an empty lane.
    pub constraint: [u32; LANES],
    body_a: [u32; LANES],
    body_b: [u32; LANES],
    /// Bit `l`: lane `l` writes body A (resp. B) back.
    writes_a: u8,
    writes_b: u8,
    /// Bit `l`: lane `l`'s contact is elastic (`ContactConstraint::elastic`).
    elastic: u8,
    /// Bit `l`: lane `l` is a column face (`ContactConstraint::column`).
    column: u8,
    /// Bit `l`: lane `l`'s friction is solved in its column's coarse correction
    /// (`ContactConstraint::column_friction`).
    column_friction: u8,
    inv_mass_a: V3,
    inv_mass_b: V3,
    normal: V3,
    tangent: [V3; 2],
    bias_rate: F,
    /// Separation up to which a row is soft (`ContactConstraint::touching`).
    touching: F,
    mass_scale: F,
    impulse_scale: F,
    restitution: F,
    points: [PointLanes; N],
    friction: F,
    tangent_impulse: [F; 2],
    tangent_mass: [F; 3],
    slide_mass: F,
    levers: L,
    manifold: M,
    /// Relative normal acceleration (gravity, forces) of the bodies, m/s², for restitution.
    bounce_accel: F,
    /// Where side A (resp. B) is held by its own supports, the unit direction it is pressed
    /// into them; else zero.
    pressing_a: V3,
    pressing_b: V3,
}

/// Sets lane `l` of `f`.
#[inline(always)]
pub(crate) fn set(f: &mut F, l: usize, value: f32) {
    f.as_mut_array()[l] = value;
}

/// `max(floor, x)` per lane where only `x` may be NaN (then `floor`): SSE `maxps` returns its
/// second operand when either is NaN.
#[inline(always)]
pub(crate) fn fmax(floor: F, x: F) -> F {
    x.fast_max(floor)
}

/// What the rows of one pass share.
#[derive(Clone, Copy)]
pub(crate) struct Pass {
    pub inv_h: f32,
    /// Soft position correction on (solve phase) or off (relax phase: speculative only).
    pub use_bias: bool,
    pub max_push: f32,
}

/// The speed below which a restitution impulse is a resting contact's jitter rather than an
/// impact: what one step of gravity, or of the pair's relative acceleration where that is
/// larger, gives (see [`ContactBatch::apply_restitution`], [`LaneResult::impact`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Jitter {
    /// The step, s.
    pub dt: f32,
    /// Gravity's magnitude, m/s².
    pub gravity: f32,
}

impl Jitter {
    /// Per lane, for relative normal accelerations `accel`, m/s.
    fn lanes(self, accel: F) -> F {
        fmax(F::splat(self.gravity), accel.abs()) * F::splat(self.dt)
    }
}

impl<const N: usize, M: ManifoldRows, L: Levers<N>> ContactBatch<N, M, L> {
    /// A batch with four empty lanes (zero masses: solving it changes nothing).
    pub(crate) const EMPTY: Self = Self {
        constraint: [u32::MAX; LANES],
        body_a: [0; LANES],
        body_b: [0; LANES],
        writes_a: 0,
        writes_b: 0,
        elastic: 0,
        column: 0,
        column_friction: 0,
        inv_mass_a: V3::ZERO,
        inv_mass_b: V3::ZERO,
        normal: V3::ZERO,
        tangent: [V3::ZERO; 2],
        bias_rate: F::ZERO,
        touching: F::ZERO,
        mass_scale: F::ZERO,
        impulse_scale: F::ZERO,
        restitution: F::ZERO,
        points: [PointLanes::EMPTY; N],
        friction: F::ZERO,
        tangent_impulse: [F::ZERO; 2],
        tangent_mass: [F::ZERO; 3],
        slide_mass: F::ZERO,
        levers: L::EMPTY,
        manifold: M::EMPTY,
        bounce_accel: F::ZERO,
        pressing_a: V3::ZERO,
        pressing_b: V3::ZERO,
    };

    /// Writes a prepared manifold into lane `l`, which reports `id` in
    /// [`ContactBatch::for_each_result`]. Lanes are written in place, one value at a time:
    /// a batch is larger than the manifold that fills one lane.
    pub(crate) fn set_lane(
        &mut self,
        l: usize,
        id: u32,
        prepared: &PreparedManifold,
        states: &[BodyState],
    ) {
        let c = &prepared.constraint;
        self.constraint[l] = id;
        self.body_a[l] = c.body_a;
        self.body_b[l] = c.body_b;
        self.writes_a |= (c.writes & 1) << l;
        self.writes_b |= ((c.writes >> 1) & 1) << l;
        self.elastic |= u8::from(c.elastic) << l;
        self.column |= u8::from(c.column) << l;
        self.column_friction |= u8::from(c.column_friction) << l;
        self.inv_mass_a
            .set(l, states[c.body_a as usize].inv_mass * c.mass_scale[0]);
        self.inv_mass_b
            .set(l, states[c.body_b as usize].inv_mass * c.mass_scale[1]);
        self.normal.set(l, c.normal);
        self.tangent[0].set(l, c.tangent[0]);
        self.tangent[1].set(l, c.tangent[1]);
        set(&mut self.bias_rate, l, c.softness.bias_rate);
        set(&mut self.touching, l, c.touching);
        set(&mut self.mass_scale, l, c.softness.mass_scale);
        set(&mut self.impulse_scale, l, c.softness.impulse_scale);
        set(&mut self.restitution, l, c.restitution);
        set(&mut self.bounce_accel, l, c.bounce_accel);
        self.pressing_a.set(l, c.pressing[0]);
        self.pressing_b.set(l, c.pressing[1]);
        let count = usize::from(c.count);
        for (lanes, p) in self.points.iter_mut().zip(&prepared.points).take(count) {
            set(&mut lanes.base_separation, l, p.base_separation);
            set(&mut lanes.normal_impulse, l, p.normal_impulse);
            set(&mut lanes.max_normal_impulse, l, p.max_normal_impulse);
            set(&mut lanes.normal_mass, l, p.normal_mass);
            set(&mut lanes.restitution_velocity, l, p.restitution_velocity);
            set(&mut lanes.restitution_impulse, l, 0.0);
        }
        let f = &c.friction;
        set(&mut self.friction, l, f.friction);
        for k in 0..2 {
            set(&mut self.tangent_impulse[k], l, f.tangent_impulse[k]);
        }
        if let Some(rows) = self.levers.rows_mut() {
            for (lanes, p) in rows.points.iter_mut().zip(&prepared.points).take(count) {
                lanes.rn_a.set(l, p.rn_a);
                lanes.rn_b.set(l, p.rn_b);
                lanes.irn_a.set(l, p.irn_a);
                lanes.irn_b.set(l, p.irn_b);
            }
            for k in 0..2 {
                rows.rt_a[k].set(l, f.rt_a[k]);
                rows.rt_b[k].set(l, f.rt_b[k]);
                rows.irt_a[k].set(l, f.irt_a[k]);
                rows.irt_b[k].set(l, f.irt_b[k]);
            }
        }
        for k in 0..3 {
            set(&mut self.tangent_mass[k], l, f.tangent_mass[k]);
        }
        set(&mut self.slide_mass, l, f.slide_mass);
        self.manifold.set_lane(l, prepared);
    }

    /// Calls `f(constraint index, impulses)` for each lane in use.
    pub(crate) fn for_each_result(&self, jitter: Jitter, mut f: impl FnMut(u32, &LaneResult)) {
        let ti = self.tangent_impulse.map(F::to_array);
        let tangent = self.tangent.map(V3::to_lanes);
        let twist = self.manifold.twist_impulse().to_array();
        let ni = self
            .points
            .map(|p| (p.normal_impulse + p.restitution_impulse).to_array());
        let max_ni = self.points.map(|p| p.max_normal_impulse.to_array());
        // What restitution added beyond the jitter's worth is an impact's, not a load's (see
        // `LaneResult::impact`).
        let jitter = jitter.lanes(self.bounce_accel);
        let impact = self.points.map(|p| {
            p.restitution_impulse
                .simd_gt(p.normal_mass * jitter)
                .to_bitmask()
        });
        for (l, &ci) in self.constraint.iter().enumerate() {
            if ci == u32::MAX {
                continue;
            }
            let mut r = LaneResult {
                tangent_impulse: [ti[0][l], ti[1][l]],
                tangent: [tangent[0][l], tangent[1][l]],
                twist_impulse: twist[l],
                column: (self.column >> l) & 1 != 0,
                ..LaneResult::default()
            };
            for k in 0..N {
                r.normal_impulse[k] = ni[k][l];
                r.max_normal_impulse[k] = max_ni[k][l];
                r.impact[k] = (impact[k] >> l) & 1 != 0;
            }
            f(ci, &r);
        }
    }

    /// Calls `f` for every lane whose contact pushed this step (a point's impulse was
    /// positive in a substep or a restitution pass).
    pub(crate) fn for_each_pushing_link(&self, mut f: impl FnMut(Link)) {
        let pushed = self.points.iter().fold(0u8, |m, p| {
            m | p.max_normal_impulse.simd_gt(F::ZERO).to_bitmask() as u8
        });
        for (l, &ci) in self.constraint.iter().enumerate() {
            if ci == u32::MAX || pushed & (1 << l) == 0 {
                continue;
            }
            let bit = |m: u8| (m >> l) & 1 != 0;
            f(Link {
                bodies: [self.body_a[l], self.body_b[l]],
                writes: [bit(self.writes_a), bit(self.writes_b)],
                elastic: bit(self.elastic),
            });
        }
    }

    /// The velocities of one side's bodies (angular ones stay zero in a linear batch).
    #[inline(always)]
    fn gather(states: &[BodyState], bodies: &[u32; LANES]) -> Velocities {
        if L::ANGULAR {
            gather_velocities(states, bodies)
        } else {
            Velocities {
                v: gather(states, bodies, |s| s.v),
                w: V3::ZERO,
            }
        }
    }

    /// Writes one side's velocities back (only linear ones from a linear batch).
    #[inline(always)]
    fn scatter(states: &mut [BodyState], bodies: &[u32; LANES], writes: u8, vel: Velocities) {
        if L::ANGULAR {
            scatter_velocities(states, bodies, writes, vel);
        } else {
            scatter_linear_velocities(states, bodies, writes, vel.v);
        }
    }

    /// Re-applies last step's impulses.
    pub(crate) fn warm_start(&self, states: &mut [BodyState]) {
        let mut a = Self::gather(states, &self.body_a);
        let mut b = Self::gather(states, &self.body_b);
        let [t1, t2] = self.tangent_impulse;
        let mut p = self.tangent[0].scale(t1) + self.tangent[1].scale(t2);
        for cp in &self.points {
            p += self.normal.scale(cp.normal_impulse);
        }
        a.v -= self.inv_mass_a * p;
        b.v += self.inv_mass_b * p;
        if let Some(rows) = self.levers.rows() {
            let mut wa = rows.irt_a[0].scale(t1) + rows.irt_a[1].scale(t2);
            let mut wb = rows.irt_b[0].scale(t1) + rows.irt_b[1].scale(t2);
            self.manifold.warm_start(&mut wa, &mut wb);
            for (cp, lever) in self.points.iter().zip(&rows.points) {
                wa += lever.irn_a.scale(cp.normal_impulse);
                wb += lever.irn_b.scale(cp.normal_impulse);
            }
            a.w -= wa;
            b.w += wb;
        }
        Self::scatter(states, &self.body_a, self.writes_a, a);
        Self::scatter(states, &self.body_b, self.writes_b, b);
    }

    /// Some lane holds a column face (see `ContactBatches::solve_columns`).
    pub(crate) fn has_column(&self) -> bool {
        self.column != 0
    }

    /// The normal rows of one pass from the bodies' current state: each point's normal
    /// velocity, its row (speculative or soft, and its bias) and the row's mass and impulse
    /// scales.
    #[inline(always)]
    fn normal_rows(
        &self,
        states: &[BodyState],
        a: &Velocities,
        b: &Velocities,
        pass: Pass,
    ) -> ([F; N], NormalRows<N>, [F; N], [F; N]) {
        let ((dp_a, dtheta_a), (dp_b, dtheta_b)) = if L::ANGULAR {
            (
                gather_deltas(states, &self.body_a),
                gather_deltas(states, &self.body_b),
            )
        } else {
            (
                (gather(states, &self.body_a, |s| s.dp), V3::ZERO),
                (gather(states, &self.body_b, |s| s.dp), V3::ZERO),
            )
        };
        let n = self.normal;
        let zero = F::ZERO;
        let one = F::ONE;
        // Linearised current separation: base + n·(Δp_b − Δp_a) + Δθ_b·(r_b×n) − Δθ_a·(r_a×n);
        // normal velocities all from the start-of-pass state (the coupling tracks them
        // through the sweep).
        let dpn = (dp_b - dp_a).dot(n);
        let dvn = (b.v - a.v).dot(n);
        let inv_h = F::splat(pass.inv_h);
        let neg_max_push = F::splat(-pass.max_push);
        let mut vn = [zero; N];
        let mut rows = NormalRows {
            speculative: [zero; N],
            bias: [zero; N],
            use_bias: pass.use_bias,
        };
        let mut mass_scale = [one; N];
        let mut impulse_scale = [zero; N];
        for k in 0..N {
            let cp = &self.points[k];
            let (sep, v) = match self.levers.rows() {
                Some(rows) => {
                    let lever = &rows.points[k];
                    (
                        cp.base_separation + dpn + dtheta_b.dot(lever.rn_b)
                            - dtheta_a.dot(lever.rn_a),
                        dvn + b.w.dot(lever.rn_b) - a.w.dot(lever.rn_a),
                    )
                }
                None => (cp.base_separation + dpn, dvn),
            };
            vn[k] = v;
            // Within rounding of touching, a point is touching (`TOUCHING_SIZE_FRACTION`).
            let speculative = sep.simd_gt(self.touching);
            rows.speculative[k] = speculative;
            if pass.use_bias {
                // No dead zone (as in Box2D v3 and rapier): a resting contact settles at the
                // soft spring's static deflection.
                let soft = fmax(neg_max_push, self.bias_rate * sep);
                rows.bias[k] = speculative.select(sep * inv_h, soft);
                mass_scale[k] = speculative.select(one, self.mass_scale);
                impulse_scale[k] = speculative.select(zero, self.impulse_scale);
            } else {
                rows.bias[k] = speculative.select(sep * inv_h, zero);
            }
        }
        (vn, rows, mass_scale, impulse_scale)
    }

    /// One Gauss–Seidel pass: the normal rows (shared step, then point by point), then
    /// friction at the manifold centre bounded by the new normal impulses.
    pub(crate) fn solve(&mut self, states: &mut [BodyState], pass: Pass) {
        let mut a = Self::gather(states, &self.body_a);
        let mut b = Self::gather(states, &self.body_b);
        let n = self.normal;
        let zero = F::ZERO;
        let (mut vn, rows, mass_scale, impulse_scale) = self.normal_rows(states, &a, &b, pass);
        let mut applied = [zero; N];
        self.manifold
            .solve_shared(&mut self.points, &rows, &mut vn, &mut applied);
        let mut leveled = self.manifold.level_patch(&self.points, &rows);
        let level_share = leveled.share;
        for j in 0..N {
            let cp = &mut self.points[j];
            let own = cp.normal_impulse;
            let leak = leveled
                .lanes
                .select(own + level_share * (leveled.mean_impulse - own), own);
            let imp =
                -cp.normal_mass * mass_scale[j] * (vn[j] + rows.bias[j]) - impulse_scale[j] * leak;
            let new = fmax(zero, cp.normal_impulse + imp);
            let imp = new - cp.normal_impulse;
            leveled.mean_impulse += imp * leveled.inv_count;
            cp.normal_impulse = new;
            cp.max_normal_impulse = fmax(cp.max_normal_impulse, imp);
            applied[j] += imp;
            self.manifold.couple(j, imp, &mut vn);
        }
        let mut total = zero;
        let (mut da, mut db) = (V3::ZERO, V3::ZERO);
        for (k, &imp) in applied.iter().enumerate() {
            total += imp;
            if let Some(rows) = self.levers.rows() {
                da += rows.points[k].irn_a.scale(imp);
                db += rows.points[k].irn_b.scale(imp);
            }
        }
        let p = n.scale(total);
        a.v -= self.inv_mass_a * p;
        b.v += self.inv_mass_b * p;
        if L::ANGULAR {
            a.w -= da;
            b.w += db;
        }
        self.solve_friction(&mut a, &mut b);
        if self.has_column() {
            // A column's passes drive its sideways and twisting rounding towards zero, into
            // subnormal floats (see `lanes::TINY_SPEED`).
            a = a.flush_tiny();
            b = b.flush_tiny();
        }
        Self::scatter(states, &self.body_a, self.writes_a, a);
        Self::scatter(states, &self.body_b, self.writes_b, b);
    }

    /// B's velocity relative to A's along the two tangents at the manifold centre.
    #[inline(always)]
    fn tangent_velocity(&self, a: &Velocities, b: &Velocities) -> [F; 2] {
        let dv = b.v - a.v;
        std::array::from_fn(|k| match self.levers.rows() {
            Some(rows) => dv.dot(self.tangent[k]) + b.w.dot(rows.rt_b[k]) - a.w.dot(rows.rt_a[k]),
            None => dv.dot(self.tangent[k]),
        })
    }

    /// Coulomb friction in the contact plane (exact 2×2 mass while sticking, isotropic while
    /// sliding), then the layout's twist friction, at the manifold centre.
    #[inline(always)]
    fn solve_friction(&mut self, a: &mut Velocities, b: &mut Velocities) {
        let max_f = self.friction_bound();
        let max_f2 = max_f * max_f;
        let [vt1, vt2] = self.tangent_velocity(a, b);
        let m = self.tangent_mass;
        let [old1, old2] = self.tangent_impulse;
        let stick1 = old1 - (m[0] * vt1 + m[1] * vt2);
        let stick2 = old2 - (m[1] * vt1 + m[2] * vt2);
        let slide1 = old1 - self.slide_mass * vt1;
        let slide2 = old2 - self.slide_mass * vt2;
        let len2 = slide1 * slide1 + slide2 * slide2;
        // The square root and division only where some lane slides past the bound (in a
        // resting pile, nearly none: they were a tenth of the 20-row pyramid's solve).
        let over = len2.simd_gt(max_f2);
        let clamp = if over.any() {
            over.select(max_f / len2.sqrt(), F::ONE)
        } else {
            F::ONE
        };
        let sliding = (stick1 * stick1 + stick2 * stick2).simd_gt(max_f2);
        let l1 = sliding.select(slide1 * clamp, stick1);
        let l2 = sliding.select(slide2 * clamp, stick2);
        self.tangent_impulse = [l1, l2];
        self.apply_tangent(a, b, [l1 - old1, l2 - old2]);
        if L::ANGULAR {
            self.manifold
                .solve_twist(&self.points, self.friction, self.normal, a, b);
        }
    }

    /// The Coulomb bound on the friction impulse at the manifold centre: the coefficient
    /// times the points' accumulated normal impulses.
    #[inline(always)]
    fn friction_bound(&self) -> F {
        let mut total = F::ZERO;
        for cp in &self.points {
            total += cp.normal_impulse;
        }
        self.friction * total
    }

    /// Moves the bodies' velocities `a` and `b` by a change `d` of the friction impulses
    /// along the two tangents at the manifold centre.
    #[inline(always)]
    fn apply_tangent(&self, a: &mut Velocities, b: &mut Velocities, [d1, d2]: [F; 2]) {
        let [t1, t2] = self.tangent;
        let p = t1.scale(d1) + t2.scale(d2);
        a.v -= self.inv_mass_a * p;
        b.v += self.inv_mass_b * p;
        if let Some(rows) = self.levers.rows() {
            a.w -= rows.irt_a[0].scale(d1) + rows.irt_a[1].scale(d2);
            b.w += rows.irt_b[0].scale(d1) + rows.irt_b[1].scale(d2);
        }
    }

    /// One restitution pass after the substeps (see [`super::restitution`]): every point of
    /// a bouncy manifold that carried load is driven to its target, one given a rebound speed
    /// to separate at that speed corrected for where the step left the bodies
    /// ([`super::restitution::stored_rebound`]), any other to its held velocity
    /// ([`super::restitution::held_velocity`]). Passes repeat Gauss–Seidel towards the
    /// simultaneous solution (a body hitting two others in one step, a ball landing on one
    /// that lies on the floor); what they add is kept apart from the substeps' impulse, and
    /// the point's whole impulse stays ≥ 0. `h` is the substep. Returns the largest change
    /// of a point's normal velocity, m/s.
    pub(crate) fn apply_restitution(
        &mut self,
        states: &mut [BodyState],
        struck: &mut [bool],
        h: f32,
        jitter: Jitter,
    ) -> f32 {
        let bouncy = self.restitution.simd_gt(F::ZERO);
        if !bouncy.any() {
            return 0.0;
        }
        // Lanes with a body some rebound (or a hold it caused) has reached this step.
        let lane_struck = F::from(std::array::from_fn::<f32, LANES, _>(|l| {
            let hit = |bodies: &[u32; LANES], writes: u8| {
                writes & (1 << l) != 0 && struck[bodies[l] as usize]
            };
            if hit(&self.body_a, self.writes_a) || hit(&self.body_b, self.writes_b) {
                1.0
            } else {
                0.0
            }
        }))
        .simd_gt(F::ZERO);
        // Less than the jitter strikes nothing (holds spread through a stack of eight boxes
        // with e = 0.5 from its contacts' small bounces, and it fell apart at fast).
        let jitter = jitter.lanes(self.bounce_accel);
        let mut impacts = F::ZERO;
        let mut change = F::ZERO;
        let mut a = Self::gather(states, &self.body_a);
        let mut b = Self::gather(states, &self.body_b);
        let ((dp_a, dtheta_a), (dp_b, dtheta_b)) = if L::ANGULAR {
            (
                gather_deltas(states, &self.body_a),
                gather_deltas(states, &self.body_b),
            )
        } else {
            (
                (gather(states, &self.body_a, |s| s.dp), V3::ZERO),
                (gather(states, &self.body_b, |s| s.dp), V3::ZERO),
            )
        };
        let n = self.normal;
        // Where the step left the bodies, but a held side where it started along the
        // direction it is pressed into its supports: an impact presses a ball lying on the
        // floor into it (the soft contact's deflection under the impact), and a rebound
        // measured from there lacks the potential energy of that depth (see `restitution`,
        // "Where the step ends"). Its motion across that direction (sliding) counts.
        let (pa, pb) = (self.pressing_a, self.pressing_b);
        let dpn = ((dp_b - pb.scale(dp_b.dot(pb))) - (dp_a - pa.scale(dp_a.dot(pa)))).dot(n);
        let accel = self.bounce_accel;
        let half_h = F::splat(0.5 * h);
        for (k, cp) in self.points.iter_mut().enumerate() {
            let loaded = cp.max_normal_impulse.simd_gt(F::ZERO);
            // A rebound speed is > 0, a held velocity ≤ 0.
            let given = cp.restitution_velocity.simd_gt(F::ZERO);
            let bounce = bouncy & loaded & given;
            let hold = bouncy & loaded & !given & lane_struck;
            if !(bounce | hold).any() {
                continue;
            }
            let lever = self.levers.rows().map(|rows| &rows.points[k]);
            let (vn, sep) = match lever {
                Some(lever) => (
                    (b.v - a.v).dot(n) + b.w.dot(lever.rn_b) - a.w.dot(lever.rn_a),
                    cp.base_separation + dpn + dtheta_b.dot(lever.rn_b) - dtheta_a.dot(lever.rn_a),
                ),
                None => ((b.v - a.v).dot(n), cp.base_separation + dpn),
            };
            let speed = given.select(cp.restitution_velocity, F::ZERO);
            let rebound =
                fmax(F::ZERO, speed * speed + F::splat(2.0) * accel * sep).sqrt() - accel * half_h;
            // A bouncing point may give back the substeps' impulse (their soft push can leave
            // it separating faster than its rebound); a held one only pushes (pulled to its
            // target, a body resting on the floor ended the step falling onto it, and
            // bounced on it every other step).
            let target = bounce.select(rebound, cp.restitution_velocity);
            let floor = bounce.select(-cp.normal_impulse, F::ZERO);
            let imp = -cp.normal_mass * (vn - target);
            let new = fmax(floor, cp.restitution_impulse + imp);
            let imp = (bounce | hold).select(new - cp.restitution_impulse, F::ZERO);
            cp.restitution_impulse += imp;
            cp.max_normal_impulse = fmax(cp.max_normal_impulse, imp);
            // Empty lanes have no mass and no impulse: 0 / 0 is NaN, which `fmax` drops.
            change = fmax(change, imp.abs() / cp.normal_mass);
            impacts = fmax(
                impacts,
                cp.restitution_impulse.abs() - cp.normal_mass * jitter,
            );
            let p = n.scale(imp);
            a.v -= self.inv_mass_a * p;
            b.v += self.inv_mass_b * p;
            if let Some(lever) = lever {
                a.w -= lever.irn_a.scale(imp);
                b.w += lever.irn_b.scale(imp);
            }
        }
        Self::scatter(states, &self.body_a, self.writes_a, a);
        Self::scatter(states, &self.body_b, self.writes_b, b);
        let moved = impacts.simd_gt(F::ZERO).to_bitmask();
        for l in 0..LANES {
            if moved & (1 << l) != 0 {
                for (bodies, writes) in
                    [(&self.body_a, self.writes_a), (&self.body_b, self.writes_b)]
                {
                    if writes & (1 << l) != 0 {
                        struck[bodies[l] as usize] = true;
                    }
                }
            }
        }
        let c = change.to_array();
        c[0].max(c[1]).max(c[2].max(c[3]))
    }
}

/// What the columns' coarse correction ([`super::column_solve`]) reads and writes of a batch
/// of faces.
impl<L: Levers<4>> ContactBatch<4, FaceContact, L> {
    /// Lane `l`'s face as the coarse correction sees it, or `None` where the lane is not a
    /// column face.
    pub(crate) fn column_face(&self, l: usize) -> Option<ColumnFace> {
        if (self.column >> l) & 1 == 0 {
            return None;
        }
        let lane = |v: &V3| v.to_lanes()[l];
        let active: [bool; 4] =
            std::array::from_fn(|k| self.manifold.active(k).to_array()[l] > 0.0);
        let zero = [Vec3A::ZERO; 4];
        let (rn, irn) = match self.levers.rows() {
            Some(rows) => (
                [
                    rows.points.map(|p| lane(&p.rn_a)),
                    rows.points.map(|p| lane(&p.rn_b)),
                ],
                [
                    rows.points.map(|p| lane(&p.irn_a)),
                    rows.points.map(|p| lane(&p.irn_b)),
                ],
            ),
            None => ([zero; 2], [zero; 2]),
        };
        let with_friction = (self.column_friction >> l) & 1 != 0;
        let friction = (with_friction && self.friction.to_array()[l] > 0.0).then(|| {
            match self.levers.rows() {
                Some(rows) => FrictionLevers {
                    rt: [rows.rt_a.map(|v| lane(&v)), rows.rt_b.map(|v| lane(&v))],
                    irt: [rows.irt_a.map(|v| lane(&v)), rows.irt_b.map(|v| lane(&v))],
                },
                None => FrictionLevers {
                    rt: [[Vec3A::ZERO; 2]; 2],
                    irt: [[Vec3A::ZERO; 2]; 2],
                },
            }
        });
        Some(ColumnFace::new(
            [self.body_a[l], self.body_b[l]],
            [(self.writes_a >> l) & 1 != 0, (self.writes_b >> l) & 1 != 0],
            lane(&self.normal),
            [lane(&self.tangent[0]), lane(&self.tangent[1])],
            [lane(&self.inv_mass_a), lane(&self.inv_mass_b)],
            active,
            rn,
            irn,
            friction,
        ))
    }

    /// The face's normal rows in `pass` as the coarse correction reads them (see
    /// [`ColumnRows`]).
    pub(crate) fn column_rows(&self, states: &[BodyState], pass: Pass) -> ColumnRows {
        let a = Self::gather(states, &self.body_a);
        let b = Self::gather(states, &self.body_b);
        let (vn, rows, mass_scale, impulse_scale) = self.normal_rows(states, &a, &b, pass);
        let leveled = self.manifold.level_patch(&self.points, &rows);
        let share = leveled.lanes.select(leveled.share, F::ZERO);
        let mut out = ColumnRows {
            residual: [F::ZERO; 4],
            compliance: [F::ZERO; 4],
            level_share: share,
            impulse: [F::ZERO; 4],
            tangent_velocity: if self.column_friction != 0 {
                self.tangent_velocity(&a, &b)
            } else {
                [F::ZERO; 2]
            },
        };
        for k in 0..4 {
            let cp = &self.points[k];
            let own = cp.normal_impulse;
            let leak = own + share * (leveled.mean_impulse - own);
            // The row's fixed point, `m·s·(vn + bias) + i·leak = 0`, over `m·s`.
            let compliance = impulse_scale[k] / (mass_scale[k] * cp.normal_mass);
            let active = self.manifold.active(k).simd_gt(F::ZERO);
            let compliance = active.select(compliance, F::ZERO);
            out.residual[k] = active.select(vn[k] + rows.bias[k] + compliance * leak, F::ZERO);
            out.compliance[k] = compliance;
            out.impulse[k] = own;
        }
        out
    }

    /// Adds `tangent` to the friction impulses (0 on lanes whose friction is not in a coarse
    /// correction), held within the friction cone of the normal impulses, and moves the
    /// bodies' velocities `a` and `b` by what was added.
    fn add_column_friction(&mut self, a: &mut Velocities, b: &mut Velocities, tangent: [F; 2]) {
        let max_f = self.friction_bound();
        let [old1, old2] = self.tangent_impulse;
        let (mut new1, mut new2) = (old1 + tangent[0], old2 + tangent[1]);
        let len2 = new1 * new1 + new2 * new2;
        // Only the lanes the correction moves (a lane's own passes bound the rest).
        let moved = tangent[0].simd_ne(F::ZERO) | tangent[1].simd_ne(F::ZERO);
        let over = len2.simd_gt(max_f * max_f) & moved;
        if over.any() {
            let scale = over.select(max_f / len2.sqrt(), F::ONE);
            new1 *= scale;
            new2 *= scale;
        }
        self.tangent_impulse = [new1, new2];
        self.apply_tangent(a, b, [new1 - old1, new2 - old2]);
    }

    /// Adds `impulse[k]` to point `k`'s normal impulse per lane (0 on lanes that are not
    /// column faces), none below zero, then `tangent` to the friction impulses (see
    /// [`Self::add_column_friction`]), and moves the bodies by what was added.
    pub(crate) fn add_column_impulses(
        &mut self,
        states: &mut [BodyState],
        impulse: [F; 4],
        tangent: [F; 2],
    ) {
        let mut a = Self::gather(states, &self.body_a);
        let mut b = Self::gather(states, &self.body_b);
        let mut sum = F::ZERO;
        let (mut da, mut db) = (V3::ZERO, V3::ZERO);
        for (k, cp) in self.points.iter_mut().enumerate() {
            let new = fmax(F::ZERO, cp.normal_impulse + impulse[k]);
            let mine = new - cp.normal_impulse;
            cp.normal_impulse = new;
            cp.max_normal_impulse = fmax(cp.max_normal_impulse, mine);
            sum += mine;
            if let Some(rows) = self.levers.rows() {
                da += rows.points[k].irn_a.scale(mine);
                db += rows.points[k].irn_b.scale(mine);
            }
        }
        let p = self.normal.scale(sum);
        a.v -= self.inv_mass_a * p;
        b.v += self.inv_mass_b * p;
        if L::ANGULAR {
            a.w -= da;
            b.w += db;
        }
        if self.column_friction != 0 {
            self.add_column_friction(&mut a, &mut b, tangent);
        }
        Self::scatter(states, &self.body_a, self.writes_a, a);
        Self::scatter(states, &self.body_b, self.writes_b, b);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_face_is_levelled_from_two_thirds_of_the_column_it_can_hold_in_tilt() {
        let g = 9.81;
        // A 1 m box on a 1 m box at 32 Hz: the face holds a column of ~45 boxes in tilt
        // (ω·√(size / 2g) = 45.4), levelled from two thirds of that, ~30.3.
        assert!(!levelled_for_load(30.0, 32.0, 1.0, g));
        assert!(levelled_for_load(30.6, 32.0, 1.0, g));
        // Stiffer faces hold twice the column at twice the stiffness; larger bodies are a
        // taller column per body (√size).
        assert!(!levelled_for_load(60.0, 64.0, 1.0, g));
        assert!(levelled_for_load(61.2, 64.0, 1.0, g));
        assert!(!levelled_for_load(60.0, 32.0, 4.0, g));
        assert!(levelled_for_load(61.2, 32.0, 4.0, g));
        // No gravity, no column to hold: never levelled for load.
        assert!(!levelled_for_load(1e6, 32.0, 1.0, 0.0));
    }
}
