//! [`JointConstraint`]: one joint's rows for a step, solved in the soft-step substeps with the
//! contacts (warm start, biased solve, relax; Box2D v3's soft step, in 3-D).
//!
//! A joint is a few groups of rows, each a velocity constraint `J v = 0` on the two bodies:
//! - the **linear block**: the anchor point (3 rows, world axes), a slider's line (2 rows
//!   across its axis) or a rod's length (1 row), solved together (`K = J M⁻¹ Jᵀ`, up to 3×3);
//! - the **angular block**: a weld's or slider's orientation (3 rows, world axes) or a
//!   hinge's axis (2 rows across it), solved together;
//! - the **free axis** (hinge angle, slider translation, distance, ball twist): a spring, a
//!   motor bounded by its force, and lower/upper limits, each one row;
//! - a ball joint's **cone** limit (one row about the axis of the swing).
//!
//! Rows are solved drives → limits → angular block → linear block (the hard rows last, so
//! they win). Block and limit rows are soft while the biased passes correct position error
//! (`PhysicsSettings::joint_hertz`, `joint_damping_ratio`) and rigid in the relax passes;
//! limits are speculative, like contacts: a limit not yet reached lets the coordinate
//! approach it by exactly the remaining gap in a substep. Springs and position motors use
//! their own stiffness.
//!
//! Geometry is relative, as for contacts: each body's anchor offset from its centre of mass
//! and its joint frame are taken at the step start and turned by the body's rotation since
//! then; the anchors' separation is `Δc + Δp_b − Δp_a + r_b − r_a` with `Δc` the centres'
//! offset at the step start, so precision does not depend on the distance from the origin.

use glam::{Mat3A, Quat, Vec3, Vec3A};

use super::body_state::BodyState;
use super::softness::Softness;
use super::solver_body::SolverBody;
use crate::joint::JointImpulses;
use crate::joint_desc::{JointKind, JointLimits, JointMotor, JointSpring, MotorTarget};

/// A pivot of a block below this share of the block's largest diagonal is taken as a row
/// the bodies cannot move along (locked axes, two static sides) and dropped from the solve.
pub const BLOCK_PIVOT_EPSILON: f32 = 1e-6;

/// Anchors closer than this, metres, give a distance joint no direction: its rows skip the
/// substep.
pub const MIN_DISTANCE_JOINT_LENGTH: f32 = 1e-6;

/// One row: the Jacobian `[−lin, −ang_a, lin, ang_b]` (body A's parts negated), with its
/// angular parts through each body's inverse inertia (`ia = I_a⁻¹ ang_a`, `ib = I_b⁻¹ ang_b`),
/// computed once per geometry (see [`JointConstraint::refresh`]) instead of in every block
/// entry and impulse: the 50-plank bridge's step cost 1.2× rapier's without it.
#[derive(Clone, Copy, Debug, Default)]
struct Row {
    lin: Vec3A,
    ang_a: Vec3A,
    ang_b: Vec3A,
    ia: Vec3A,
    ib: Vec3A,
}

impl Row {
    fn angular(axis: Vec3A) -> Self {
        Self {
            lin: Vec3A::ZERO,
            ang_a: axis,
            ang_b: axis,
            ..Self::default()
        }
    }

    /// A linear row along `u` between anchors at `ra` and `rb` from the centres of mass.
    fn linear(u: Vec3A, ra: Vec3A, rb: Vec3A) -> Self {
        Self {
            lin: u,
            ang_a: ra.cross(u),
            ang_b: rb.cross(u),
            ..Self::default()
        }
    }

    fn negated(self) -> Self {
        Self {
            lin: -self.lin,
            ang_a: -self.ang_a,
            ang_b: -self.ang_b,
            ia: -self.ia,
            ib: -self.ib,
        }
    }
}

/// The two bodies' velocities while a joint is solved.
#[derive(Clone, Copy, Debug)]
struct Velocities {
    va: Vec3A,
    wa: Vec3A,
    vb: Vec3A,
    wb: Vec3A,
}

/// Soft-row coefficients for one pass: the Box2D v3 soft step, or rigid.
#[derive(Clone, Copy, Debug)]
struct Coeffs {
    bias_rate: f32,
    mass_scale: f32,
    impulse_scale: f32,
}

const RIGID: Coeffs = Coeffs {
    bias_rate: 0.0,
    mass_scale: 1.0,
    impulse_scale: 0.0,
};

impl From<Softness> for Coeffs {
    fn from(s: Softness) -> Self {
        Self {
            bias_rate: s.bias_rate,
            mass_scale: s.mass_scale,
            impulse_scale: s.impulse_scale,
        }
    }
}

/// A row solved alone (free axis, cone), with its coordinate and its effective mass.
#[derive(Clone, Copy, Debug, Default)]
struct Single {
    row: Row,
    /// The free coordinate, or the cone's remaining angle `cone − swing`.
    x: f32,
    /// `1 / (J M⁻¹ Jᵀ)`, 0 where the bodies cannot move along the row.
    mass: f32,
}

impl Single {
    fn new(row: Row, x: f32) -> Self {
        Self { row, x, mass: 0.0 }
    }
}

/// `K = LDLᵀ` of a block (see [`factor`], [`block_inverse`]).
#[derive(Clone, Copy, Debug, Default)]
struct Factor {
    l: [[f32; 3]; 3],
    /// The pivots; 0 for a row the bodies cannot move along.
    d: [f32; 3],
}

/// Up to three equality rows solved together, with the position error of each.
#[derive(Clone, Copy, Debug, Default)]
struct Block {
    rows: [Row; 3],
    c: [f32; 3],
    n: usize,
    /// `K⁻¹` with the rows that cannot move dropped ([`block_inverse`]), 0 past `n`: found
    /// once per build of the rows, so that each pass is a product. Factoring `K` in every
    /// pass was 18 % of the 50-plank bridge's step.
    inv: Mat3A,
}

/// Every row of a joint at the bodies' poses of the current pass, with the position error of
/// each ([`JointConstraint::refresh`]). Positions move only between the biased and the relax
/// passes, so they are built once at the step start and once after each substep's move, not
/// once per warm start and pass. Kept apart from the [`JointConstraint`] (the solver holds
/// one per joint), so that a build writes them in place: building them into the joint was a
/// copy of ~1 kB per build.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Rows {
    /// The free axis (absent for a weld, or a rod with no direction).
    axis: Option<Single>,
    /// A ball joint's cone.
    cone: Option<Single>,
    lin: Block,
    ang: Block,
}

/// A joint prepared for one step (see the module docs).
#[derive(Clone, Copy, Debug)]
pub(crate) struct JointConstraint {
    /// Arena index of the joint (its impulses are written back there).
    pub joint: u32,
    /// Solver indices of the bodies (0: static, asleep or the world).
    pub body_a: u32,
    pub body_b: u32,
    /// Bit 0: the solver writes A's velocities; bit 1: B's.
    pub writes: u8,
    pub inv_mass_a: Vec3A,
    pub inv_mass_b: Vec3A,
    pub inv_i_a: Mat3A,
    pub inv_i_b: Mat3A,
    /// Anchor offsets from each centre of mass at the step start, world axes.
    pub r_a0: Vec3A,
    pub r_b0: Vec3A,
    /// Joint frames in world axes at the step start.
    pub frame_a0: Quat,
    pub frame_b0: Quat,
    /// `c_b − c_a` at the step start (centres of mass; the world side's anchor).
    pub delta_center: Vec3A,
    pub kind: JointKind,
    /// The position rows' softness (`joint_hertz`, `joint_damping_ratio`).
    pub softness: Softness,
    /// The spring's and the position motor's softness.
    pub spring_softness: Softness,
    pub motor_softness: Softness,
    pub inv_h: f32,
    pub h: f32,
    pub impulses: JointImpulses,
}

/// The angle of `q` about X, in (−π, π] (the twist of a swing–twist decomposition).
fn twist_angle(q: Quat) -> f32 {
    let q = if q.w < 0.0 { -q } else { q };
    2.0 * q.x.atan2(q.w)
}

/// `a − b` wrapped into (−π, π].
fn angle_difference(a: f32, b: f32) -> f32 {
    let tau = std::f32::consts::TAU;
    let d = (a - b).rem_euclid(tau);
    if d > std::f32::consts::PI {
        d - tau
    } else {
        d
    }
}

/// Factors a symmetric positive semi-definite `K` of `n ≤ 3` rows as `LDLᵀ`, dropping rows
/// whose pivot is below [`BLOCK_PIVOT_EPSILON`] of the largest diagonal (see [`substitute`]).
fn factor(k: &[[f32; 3]; 3], n: usize) -> Factor {
    let scale = (0..n).map(|i| k[i][i]).fold(0.0f32, f32::max);
    let mut l = [[0.0f32; 3]; 3];
    let mut d = [0.0f32; 3];
    let eps = BLOCK_PIVOT_EPSILON * scale;
    for j in 0..n {
        let mut dj = k[j][j];
        for m in 0..j {
            dj -= l[j][m] * l[j][m] * d[m];
        }
        d[j] = if dj > eps { dj } else { 0.0 };
        for i in j + 1..n {
            let mut lij = k[i][j];
            for m in 0..j {
                lij -= l[i][m] * l[j][m] * d[m];
            }
            l[i][j] = if d[j] > 0.0 { lij / d[j] } else { 0.0 };
        }
    }
    Factor { l, d }
}

/// The linear map `b ↦ x` of [`substitute`] as a matrix (0 past `n`): by the cofactors where
/// every pivot is kept (one division), else column by column from the `LDLᵀ` factors.
fn block_inverse(k: &[[f32; 3]; 3], n: usize) -> Mat3A {
    let scale = (0..n).map(|i| k[i][i]).fold(0.0f32, f32::max);
    let eps = BLOCK_PIVOT_EPSILON * scale;
    // The pivots of `LDLᵀ` are the ratios of the leading minors: d₀ = m₁, d₁ = m₂/m₁,
    // d₂ = m₃/m₂; each compared with `eps` as `factor` does, without the divisions.
    let m1 = k[0][0];
    let m2 = k[0][0] * k[1][1] - k[0][1] * k[0][1];
    let inv = match n {
        0 => return Mat3A::ZERO,
        1 if m1 > eps => Some(Mat3A::from_diagonal(Vec3::new(1.0 / m1, 0.0, 0.0))),
        2 if m1 > eps && m2 > eps * m1 => {
            let r = 1.0 / m2;
            Some(Mat3A::from_cols(
                Vec3A::new(k[1][1] * r, -k[0][1] * r, 0.0),
                Vec3A::new(-k[0][1] * r, k[0][0] * r, 0.0),
                Vec3A::ZERO,
            ))
        }
        3 => {
            // Cofactors of the symmetric `K`.
            let c00 = k[1][1] * k[2][2] - k[1][2] * k[1][2];
            let c01 = k[0][2] * k[1][2] - k[0][1] * k[2][2];
            let c02 = k[0][1] * k[1][2] - k[0][2] * k[1][1];
            let c11 = k[0][0] * k[2][2] - k[0][2] * k[0][2];
            let c12 = k[0][1] * k[0][2] - k[0][0] * k[1][2];
            let c22 = m2;
            let m3 = k[0][0] * c00 + k[0][1] * c01 + k[0][2] * c02;
            (m1 > eps && m2 > eps * m1 && m3 > eps * m2).then(|| {
                let r = 1.0 / m3;
                Mat3A::from_cols(
                    Vec3A::new(c00, c01, c02) * r,
                    Vec3A::new(c01, c11, c12) * r,
                    Vec3A::new(c02, c12, c22) * r,
                )
            })
        }
        _ => None,
    };
    inv.unwrap_or_else(|| {
        let f = factor(k, n);
        let col = |i: usize| {
            let mut e = [0.0f32; 3];
            e[i] = 1.0;
            Vec3A::from(substitute(&f, e, n))
        };
        Mat3A::from_cols(col(0), col(1), col(2))
    })
}

/// Solves `K x = b` with `K`'s [`factor`]; a dropped row's `x` is 0.
fn substitute(f: &Factor, b: [f32; 3], n: usize) -> [f32; 3] {
    let (l, d) = (&f.l, &f.d);
    // L y = b, D z = y, Lᵀ x = z.
    let mut y = [0.0f32; 3];
    for i in 0..n {
        let mut s = b[i];
        for m in 0..i {
            s -= l[i][m] * y[m];
        }
        y[i] = s;
    }
    let mut x = [0.0f32; 3];
    for i in (0..n).rev() {
        let mut s = if d[i] > 0.0 { y[i] / d[i] } else { 0.0 };
        for m in i + 1..n {
            s -= l[m][i] * x[m];
        }
        x[i] = if d[i] > 0.0 { s } else { 0.0 };
    }
    x
}

impl JointConstraint {
    fn cdot(&self, r: &Row, v: &Velocities) -> f32 {
        r.lin.dot(v.vb - v.va) + r.ang_b.dot(v.wb) - r.ang_a.dot(v.wa)
    }

    fn apply(&self, r: &Row, impulse: f32, v: &mut Velocities) {
        v.va -= self.inv_mass_a * r.lin * impulse;
        v.wa -= r.ia * impulse;
        v.vb += self.inv_mass_b * r.lin * impulse;
        v.wb += r.ib * impulse;
    }

    /// `J₁ M⁻¹ J₂ᵀ`.
    fn k(&self, r1: &Row, r2: &Row) -> f32 {
        r1.lin.dot((self.inv_mass_a + self.inv_mass_b) * r2.lin)
            + r1.ang_a.dot(r2.ia)
            + r1.ang_b.dot(r2.ib)
    }

    fn load(&self, states: &[BodyState]) -> Velocities {
        let (a, b) = (&states[self.body_a as usize], &states[self.body_b as usize]);
        Velocities {
            va: a.v,
            wa: a.w,
            vb: b.v,
            wb: b.w,
        }
    }

    fn store(&self, states: &mut [BodyState], v: &Velocities) {
        if self.writes & 1 != 0 {
            let a = &mut states[self.body_a as usize];
            a.v = v.va;
            a.w = v.wa;
        }
        if self.writes & 2 != 0 {
            let b = &mut states[self.body_b as usize];
            b.v = v.vb;
            b.w = v.wb;
        }
    }

    /// Builds the rows at the bodies' current poses (`dq`, `dp` of the substep) for the passes
    /// that follow.
    pub(crate) fn refresh(&self, bodies: &[SolverBody], states: &[BodyState], rows: &mut Rows) {
        let (qa, qb) = (
            bodies[self.body_a as usize].dq,
            bodies[self.body_b as usize].dq,
        );
        let ra = qa * self.r_a0;
        let rb = qb * self.r_b0;
        let d = self.delta_center
            + (states[self.body_b as usize].dp - states[self.body_a as usize].dp)
            + (rb - ra);
        let fa = qa * self.frame_a0;
        let fb = qb * self.frame_b0;
        let ax = Vec3A::from(fa * Vec3::X);
        *rows = Rows::default();
        let point = |rows: &mut Rows| {
            for (i, e) in [Vec3A::X, Vec3A::Y, Vec3A::Z].into_iter().enumerate() {
                rows.lin.rows[i] = Row::linear(e, ra, rb);
                rows.lin.c[i] = d[i];
            }
            rows.lin.n = 3;
        };
        let weld = |rows: &mut Rows| {
            let e = fb * fa.inverse();
            let e = if e.w < 0.0 { -e } else { e };
            let c = 2.0 * Vec3A::new(e.x, e.y, e.z);
            for (i, axis) in [Vec3A::X, Vec3A::Y, Vec3A::Z].into_iter().enumerate() {
                rows.ang.rows[i] = Row::angular(axis);
                rows.ang.c[i] = c[i];
            }
            rows.ang.n = 3;
        };
        match self.kind {
            JointKind::Fixed => {
                weld(rows);
                point(rows);
            }
            JointKind::Revolute {
                limits,
                motor,
                spring,
            } => {
                // The free axis only where something acts on it (its angle costs an atan2).
                if limits.is_some() || motor.is_some() || spring.is_some() {
                    rows.axis = Some(Single::new(
                        Row::angular(ax),
                        twist_angle(fa.inverse() * fb),
                    ));
                }
                let bx = Vec3A::from(fb * Vec3::X);
                let c = ax.cross(bx);
                for (i, t) in [fa * Vec3::Y, fa * Vec3::Z].into_iter().enumerate() {
                    let t = Vec3A::from(t);
                    rows.ang.rows[i] = Row::angular(t);
                    rows.ang.c[i] = t.dot(c);
                }
                rows.ang.n = 2;
                point(rows);
            }
            JointKind::Prismatic { .. } => {
                // The axis and its cross axes turn with A: their rows take the lever `ra + d`.
                let lever = ra + d;
                rows.axis = Some(Single::new(Row::linear(ax, lever, rb), ax.dot(d)));
                weld(rows);
                for (i, t) in [fa * Vec3::Y, fa * Vec3::Z].into_iter().enumerate() {
                    let t = Vec3A::from(t);
                    rows.lin.rows[i] = Row::linear(t, lever, rb);
                    rows.lin.c[i] = t.dot(d);
                }
                rows.lin.n = 2;
            }
            JointKind::Spherical { cone, twist } => {
                let bx = Vec3A::from(fb * Vec3::X);
                if twist.is_some() {
                    let mid = (ax + bx).normalize_or_zero();
                    let twist_axis = if mid == Vec3A::ZERO { bx } else { mid };
                    rows.axis = Some(Single::new(
                        Row::angular(twist_axis),
                        twist_angle(fa.inverse() * fb),
                    ));
                }
                if let Some(cone) = cone {
                    let n = ax.cross(bx);
                    let sin = n.length();
                    if sin > 1e-6 {
                        let swing = ax.dot(bx).clamp(-1.0, 1.0).acos();
                        // d(swing)/dt = n̂·(w_b − w_a): the row is −n̂.
                        rows.cone = Some(Single::new(Row::angular(-n / sin), cone - swing));
                    }
                }
                point(rows);
            }
            JointKind::Distance { min, max, .. } => {
                let length = d.length();
                if length > MIN_DISTANCE_JOINT_LENGTH {
                    let row = Row::linear(d / length, ra, rb);
                    if min == max {
                        rows.lin.rows[0] = row;
                        rows.lin.c[0] = length - min;
                        rows.lin.n = 1;
                    } else {
                        rows.axis = Some(Single::new(row, length));
                    }
                }
            }
        }
        self.weigh(rows);
    }

    /// Fills each row's angular parts through the inverse inertias (`Row::ia`, `Row::ib`),
    /// the single rows' masses and the blocks' factors: all fixed until the next build.
    fn weigh(&self, rows: &mut Rows) {
        let weigh = |r: &mut Row| {
            r.ia = self.inv_i_a * r.ang_a;
            r.ib = self.inv_i_b * r.ang_b;
        };
        for s in [rows.axis.as_mut(), rows.cone.as_mut()]
            .into_iter()
            .flatten()
        {
            weigh(&mut s.row);
            s.mass = self.mass(&s.row);
        }
        for b in [&mut rows.lin, &mut rows.ang] {
            b.rows[..b.n].iter_mut().for_each(weigh);
            let mut k = [[0.0f32; 3]; 3];
            let rows = &b.rows[..b.n];
            for (i, ri) in rows.iter().enumerate() {
                for (j, rj) in rows.iter().enumerate().skip(i) {
                    let kij = self.k(ri, rj);
                    k[i][j] = kij;
                    k[j][i] = kij;
                }
            }
            b.inv = block_inverse(&k, b.n);
        }
    }

    /// Applies last substep's impulses (Box2D v3 warm start), at the refreshed geometry.
    pub(crate) fn warm_start(&self, rows: &Rows, states: &mut [BodyState]) {
        let mut v = self.load(states);
        let im = &self.impulses;
        if let Some(axis) = &rows.axis {
            self.apply(
                &axis.row,
                im.spring + im.motor + im.lower - im.upper,
                &mut v,
            );
        }
        if let Some(cone) = &rows.cone {
            self.apply(&cone.row, im.cone, &mut v);
        }
        for i in 0..rows.ang.n {
            self.apply(&rows.ang.rows[i], im.angular[i], &mut v);
        }
        for i in 0..rows.lin.n {
            self.apply(&rows.lin.rows[i], im.linear[i], &mut v);
        }
        self.store(states, &v);
    }

    /// One Gauss–Seidel pass over the joint's rows at the refreshed geometry: biased
    /// (`use_bias`, position error fed back softly) or relaxing (rigid, no bias).
    pub(crate) fn solve(&mut self, rows: &Rows, states: &mut [BodyState], use_bias: bool) {
        let mut im = self.impulses;
        let mut v = self.load(states);
        let soft = if use_bias {
            Coeffs::from(self.softness)
        } else {
            RIGID
        };
        let (limits, motor, spring, angular) = match self.kind {
            JointKind::Revolute {
                limits,
                motor,
                spring,
            } => (limits, motor, spring, true),
            JointKind::Prismatic {
                limits,
                motor,
                spring,
            } => (limits, motor, spring, false),
            JointKind::Spherical { twist, .. } => (twist, None, None, true),
            JointKind::Distance { min, max, spring } => (
                Some(JointLimits {
                    lower: min,
                    upper: max,
                }),
                None,
                spring,
                false,
            ),
            JointKind::Fixed => (None, None, None, false),
        };
        if let Some(axis) = &rows.axis {
            let x = axis.x;
            let error = |target: f32| {
                if angular {
                    angle_difference(x, target)
                } else {
                    x - target
                }
            };
            let (row, mass) = (&axis.row, axis.mass);
            if let Some(s) = spring {
                self.spring_row(row, mass, error(s.rest), &mut im.spring, &mut v);
            }
            if let Some(m) = motor {
                self.motor_row(row, mass, m, &error, &mut im.motor, &mut v);
            }
            if let Some(l) = limits {
                // A rope's lower bound of 0 never acts.
                if !(matches!(self.kind, JointKind::Distance { .. }) && l.lower <= 0.0) {
                    self.limit_row(row, mass, x - l.lower, &mut im.lower, soft, &mut v);
                }
                let upper = row.negated();
                self.limit_row(&upper, mass, l.upper - x, &mut im.upper, soft, &mut v);
            }
        }
        if let Some(cone) = &rows.cone {
            self.limit_row(&cone.row, cone.mass, cone.x, &mut im.cone, soft, &mut v);
        }
        self.block(&rows.ang, &mut im.angular, soft, &mut v);
        self.block(&rows.lin, &mut im.linear, soft, &mut v);
        self.impulses = im;
        self.store(states, &v);
    }

    /// A block's equality rows, solved together with its factored `K`.
    fn block(&self, b: &Block, acc: &mut [f32; 3], soft: Coeffs, v: &mut Velocities) {
        let n = b.n;
        if n == 0 {
            return;
        }
        let mut rhs = [0.0f32; 3];
        for ((rhs, r), c) in rhs.iter_mut().zip(&b.rows[..n]).zip(b.c) {
            *rhs = self.cdot(r, v) + soft.bias_rate * c;
        }
        let x = b.inv * Vec3A::from(rhs);
        for i in 0..n {
            let impulse = -soft.mass_scale * x[i] - soft.impulse_scale * acc[i];
            acc[i] += impulse;
            self.apply(&b.rows[i], impulse, v);
        }
    }

    fn mass(&self, r: &Row) -> f32 {
        let k = self.k(r, r);
        if k > 0.0 {
            1.0 / k
        } else {
            0.0
        }
    }

    /// A spring toward the rest coordinate (`error` = coordinate − rest), both passes; `m`
    /// is the row's mass and `acc` its accumulated impulse.
    fn spring_row(&self, r: &Row, m: f32, error: f32, acc: &mut f32, v: &mut Velocities) {
        let s = Coeffs::from(self.spring_softness);
        let impulse =
            -m * s.mass_scale * (self.cdot(r, v) + s.bias_rate * error) - s.impulse_scale * *acc;
        *acc += impulse;
        self.apply(r, impulse, v);
    }

    /// A motor toward a speed or a coordinate, its accumulated impulse bounded by its force.
    fn motor_row(
        &self,
        r: &Row,
        m: f32,
        motor: JointMotor,
        error: &dyn Fn(f32) -> f32,
        acc_motor: &mut f32,
        v: &mut Velocities,
    ) {
        let cdot = self.cdot(r, v);
        let acc = *acc_motor;
        let impulse = match motor.target {
            MotorTarget::Velocity(speed) => -m * (cdot - speed),
            MotorTarget::Position { target, .. } => {
                let s = Coeffs::from(self.motor_softness);
                -m * s.mass_scale * (cdot + s.bias_rate * error(target)) - s.impulse_scale * acc
            }
        };
        let bound = motor.max_force * self.h;
        let new = (acc + impulse).clamp(-bound, bound);
        *acc_motor = new;
        self.apply(r, new - acc, v);
    }

    /// A one-sided row keeping `c ≥ 0`: speculative while `c > 0` (the gap may close by
    /// exactly `c` this substep), soft (`soft`) once past it. `m` is the row's mass.
    fn limit_row(&self, r: &Row, m: f32, c: f32, acc: &mut f32, soft: Coeffs, v: &mut Velocities) {
        let (bias, ms, is) = if c > 0.0 {
            (c * self.inv_h, 1.0, 0.0)
        } else {
            (soft.bias_rate * c, soft.mass_scale, soft.impulse_scale)
        };
        let impulse = -m * ms * (self.cdot(r, v) + bias) - is * *acc;
        let new = (*acc + impulse).max(0.0);
        self.apply(r, new - *acc, v);
        *acc = new;
    }

    /// The force (N) and torque (N·m) on body B over the last substep, from the accumulated
    /// impulses at `rows`, those of the last [`JointConstraint::refresh`] (the solver leaves
    /// them at the bodies' final poses).
    pub(crate) fn reaction(&self, rows: &Rows) -> (Vec3, Vec3) {
        let im = &self.impulses;
        let (mut force, mut torque) = (Vec3A::ZERO, Vec3A::ZERO);
        let mut add = |r: &Row, impulse: f32| {
            force += r.lin * impulse;
            if r.lin == Vec3A::ZERO {
                torque += r.ang_b * impulse;
            }
        };
        if let Some(axis) = &rows.axis {
            add(&axis.row, im.spring + im.motor + im.lower - im.upper);
        }
        if let Some(cone) = &rows.cone {
            add(&cone.row, im.cone);
        }
        for i in 0..rows.ang.n {
            add(&rows.ang.rows[i], im.angular[i]);
        }
        for i in 0..rows.lin.n {
            add(&rows.lin.rows[i], im.linear[i]);
        }
        (
            Vec3::from(force) * self.inv_h,
            Vec3::from(torque) * self.inv_h,
        )
    }
}

/// The softness of a spring or position motor, if it has one.
pub(crate) fn drive_softness(
    spring: Option<JointSpring>,
    motor: Option<JointMotor>,
    h: f32,
) -> (Softness, Softness) {
    let spring = spring.map_or(Softness::RIGID, |s| {
        Softness::new(s.hertz, s.damping_ratio, h)
    });
    let motor = match motor.map(|m| m.target) {
        Some(MotorTarget::Position {
            hertz,
            damping_ratio,
            ..
        }) => Softness::new(hertz, damping_ratio, h),
        _ => Softness::RIGID,
    };
    (spring, motor)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_solve_exactly_and_drop_rows_that_cannot_move() {
        let k = [[4.0, 1.0, 0.5], [1.0, 3.0, 0.25], [0.5, 0.25, 2.0]];
        let b = [1.0, -2.0, 0.5];
        let x = substitute(&factor(&k, 3), b, 3);
        for i in 0..3 {
            let r: f32 = (0..3).map(|j| k[i][j] * x[j]).sum();
            assert!((r - b[i]).abs() < 1e-5, "row {i}: {r} vs {}", b[i]);
        }
        // A row with no mass (locked) gets no impulse; the others are still solved.
        let k = [[2.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 4.0]];
        assert_eq!(
            substitute(&factor(&k, 3), [2.0, 5.0, 2.0], 3),
            [1.0, 0.0, 0.5]
        );
    }

    #[test]
    fn block_inverses_match_the_factored_solve() {
        let x_of = |k: &[[f32; 3]; 3], b: [f32; 3], n: usize| {
            let x = block_inverse(k, n) * Vec3A::from(b);
            [x.x, x.y, x.z]
        };
        // Full rank, 1 to 3 rows (the closed forms), and rows that cannot move (the factors).
        let full = [[4.0, 1.0, 0.5], [1.0, 3.0, 0.25], [0.5, 0.25, 2.0]];
        let locked = [[2.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 4.0]];
        let singular = [[1.0, 1.0, 0.0], [1.0, 1.0, 0.0], [0.0, 0.0, 3.0]];
        let b = [1.0, -2.0, 0.5];
        for k in [full, locked, singular] {
            for n in 1..=3 {
                let want = substitute(&factor(&k, n), b, n);
                let got = x_of(&k, b, n);
                for i in 0..3 {
                    assert!(
                        (got[i] - want[i]).abs() <= 1e-5 * want[i].abs().max(1.0),
                        "n {n}, row {i}: {got:?} vs {want:?} for {k:?}"
                    );
                }
            }
        }
        assert_eq!(x_of(&locked, [2.0, 5.0, 2.0], 3), [1.0, 0.0, 0.5]);
        assert_eq!(block_inverse(&full, 0), Mat3A::ZERO);
    }

    #[test]
    fn angles_wrap_into_a_half_turn() {
        let pi = std::f32::consts::PI;
        assert!((angle_difference(3.0, -3.0) - (6.0 - 2.0 * pi)).abs() < 1e-5);
        assert!((angle_difference(-3.0, 3.0) + (6.0 - 2.0 * pi)).abs() < 1e-5);
        let q = Quat::from_rotation_x(2.5);
        assert!((twist_angle(q) - 2.5).abs() < 1e-5);
        assert!((twist_angle(-q) - 2.5).abs() < 1e-5);
    }
}
