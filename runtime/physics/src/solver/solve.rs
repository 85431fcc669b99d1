//! [`solve_substeps`]: the soft-step loop (integrate velocities → warm start → solve →
//! integrate positions → relax, per substep; restitution at the end).

use glam::{Quat, Vec3, Vec3A};

use super::batching::ContactBatches;
use super::body_state::BodyState;
use super::contact_batch::{Jitter, Pass};
use super::elastic_energy::ElasticEnergy;
use super::free_rotation::free_rotation_step;
use super::joint_constraint::{JointConstraint, Rows};
use super::solver_body::{SolverBody, CAPPED_ANGULAR, CAPPED_LINEAR};
use crate::pose::unit_rotation;

/// Most restitution passes after the substeps (see `ContactBatch::apply_restitution`).
/// Each pass is one more Gauss–Seidel sweep towards the simultaneous rebound of every
/// bouncing and held point; they stop once no pass changes a point's normal velocity by more
/// than [`RESTITUTION_TOLERANCE`]. 50 elastic balls in a box need 1.5–5 passes a step on
/// average and reach this cap in fewer than one step in 5,000; at a fixed 4 passes they lost
/// 20 % of their energy over 10,000 steps under gravity, at 16 still 1.5 %.
pub const MAX_RESTITUTION_PASSES: u32 = 32;

/// Largest change of a point's normal velocity, m/s, of a restitution pass after which the
/// passes stop.
pub const RESTITUTION_TOLERANCE: f32 = 1e-4;

/// Passes over the batches holding a column face after each substep's iterations, each
/// after a coarse correction of every column as a whole (`column_solve`; see
/// `contact_batch::column_face`). A column of small cubes whose faces are levelled in tilt
/// stands only once the column converges, not each face: with no more passes five 1 cm
/// cubes fell at 60 Hz × 4 (sooner than unlevelled); Gauss–Seidel passes alone needed 32 to
/// hold faces at half the substep rate and 256 at the substep rate. With the coarse
/// correction before each pass, faces up to twice the substep rate
/// (`softness::COLUMN_MAX_SUBSTEP_FRACTION`) hold every column of `tests/stacking.rs` within
/// 2 % from 12 passes; with 8, five 1 mm cubes at 60 Hz × 4 settled 16 % deep and ten fell.
/// Bounded `[0, ∞)`: each pass costs one solve of those batches and of each column's coarse
/// system, and only columns have them.
pub const COLUMN_PASSES: u32 = 16;

/// Passes over the columns a substep where no column face is stiffened by its depth budget
/// past `contact_batch::COLUMN_STIFFNESS` (faces taken for a column for their chain,
/// `column_chain::ChainFace::needs_column`, and the base faces under them). Such a column
/// converges in one: twenty 1 m boxes at 60 Hz × 4 stand from one pass, and cost 0.23 ms a
/// step with all [`COLUMN_PASSES`], 0.14 ms with two.
pub const SOFT_COLUMN_PASSES: u32 = 2;

/// Passes over the columns a substep: [`COLUMN_PASSES`] where some column face is one its
/// depth budget stiffened past `contact_batch::COLUMN_STIFFNESS` (`budget_column`), else
/// [`SOFT_COLUMN_PASSES`].
#[must_use]
pub fn column_passes(budget_column: bool) -> u32 {
    if budget_column {
        COLUMN_PASSES
    } else {
        SOFT_COLUMN_PASSES
    }
}

/// Parameters of one solver run (derived from `PhysicsSettings`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SolveParams {
    pub dt: f32,
    pub substeps: u32,
    pub iterations: u32,
    pub relax_iterations: u32,
    pub max_push: f32,
    /// Some manifold of the step has restitution (else the restitution passes are skipped).
    pub restitution: bool,
    pub max_linear_speed: f32,
    pub max_angular_speed: f32,
    /// Passes over the columns a substep (see [`column_passes`]).
    pub column_passes: u32,
    /// Below it a restitution impulse is a resting contact's, not an impact's.
    pub jitter: Jitter,
}

/// Runs all substeps over awake bodies, their joints and their contact batches (joints
/// before contacts in each pass, as Box2D v3 orders them). Returns how many free-rotation
/// solves missed their tolerance (see [`free_rotation_step`]). `rows` holds each joint's rows,
/// parallel to `joints` (its length is theirs). `elastic`, where some contact is elastic,
/// keeps the energy of elastic impacts (see [`super::elastic_energy`]).
pub(crate) fn solve_substeps(
    bodies: &mut [SolverBody],
    states: &mut [BodyState],
    batches: &mut ContactBatches,
    joints: &mut [JointConstraint],
    rows: &mut [Rows],
    p: &SolveParams,
    elastic: Option<&mut ElasticEnergy>,
) -> u32 {
    let mut not_converged = 0;
    let mut elastic = elastic.filter(|_| p.restitution);
    if let Some(e) = elastic.as_deref_mut() {
        e.record_start(states);
    }
    let substeps = p.substeps.max(1);
    let h = p.dt / substeps as f32;
    let solve_pass = Pass {
        inv_h: 1.0 / h,
        use_bias: true,
        max_push: p.max_push,
    };
    let relax_pass = Pass {
        use_bias: false,
        ..solve_pass
    };
    // Joint rows are built once per pose: here, and after each substep moves the bodies
    // (the relax passes and the next substep's warm start and biased passes all see those
    // poses; building again at each substep's start cost a third of the bridge's joints).
    debug_assert_eq!(joints.len(), rows.len());
    for (j, r) in joints.iter().zip(rows.iter_mut()) {
        j.refresh(bodies, states, r);
    }
    let columns = batches.has_columns();
    for _ in 0..substeps {
        integrate_velocities(bodies, states, h);
        for (j, r) in joints.iter().zip(rows.iter()) {
            j.warm_start(r, states);
        }
        batches.warm_start(states);
        for _ in 0..p.iterations.max(1) {
            for (j, r) in joints.iter_mut().zip(rows.iter()) {
                j.solve(r, states, true);
            }
            batches.solve(states, solve_pass);
        }
        if columns {
            for _ in 0..p.column_passes {
                batches.correct_columns(states, solve_pass);
                batches.solve_columns(states, solve_pass);
            }
        }
        not_converged += integrate_positions(bodies, states, h, p);
        for (j, r) in joints.iter().zip(rows.iter_mut()) {
            j.refresh(bodies, states, r);
        }
        for _ in 0..p.relax_iterations {
            for (j, r) in joints.iter_mut().zip(rows.iter()) {
                j.solve(r, states, false);
            }
            batches.solve(states, relax_pass);
        }
    }
    if p.restitution {
        if let Some(e) = elastic.as_deref_mut() {
            e.record_before(states);
        }
        let mut struck = vec![false; states.len()];
        for _ in 0..MAX_RESTITUTION_PASSES {
            if batches.apply_restitution(states, &mut struck, h, p.jitter) <= RESTITUTION_TOLERANCE
            {
                break;
            }
        }
        if let Some(e) = elastic {
            e.project(bodies, states, &struck, batches, joints, h);
        }
    }
    // The relax and restitution passes run after the last move: the velocities the step
    // leaves are held to the caps too (a capsule struck off centre at 700 m/s left the step
    // spinning at 7,000 rad/s under a 200 rad/s cap).
    for (b, st) in bodies.iter_mut().zip(states.iter_mut()).skip(1) {
        clamp_to_caps(b, st, p.max_linear_speed, p.max_angular_speed);
    }
    not_converged
}

fn integrate_velocities(bodies: &[SolverBody], states: &mut [BodyState], h: f32) {
    for (b, st) in bodies.iter().zip(states.iter_mut()).skip(1) {
        let v = (st.v + b.lin_acc * h) * b.lin_damp_factor;
        let w = (st.w + b.ang_acc * h) * b.ang_damp_factor;
        st.v = v * b.lin_mask;
        st.w = w * b.ang_mask;
    }
}

/// Clamps a body's solved velocities to the speed caps before they move it, and marks in
/// `b.capped` which cap it hit ([`CAPPED_LINEAR`], [`CAPPED_ANGULAR`]).
#[inline]
fn clamp_to_caps(b: &mut SolverBody, st: &mut BodyState, max_v: f32, max_w: f32) {
    // Squared lengths against squared limits: no square root for the common case.
    let vl2 = st.v.length_squared();
    if vl2 > max_v * max_v {
        st.v *= max_v / vl2.sqrt();
        b.capped |= CAPPED_LINEAR;
    }
    let wl2 = st.w.length_squared();
    if wl2 > max_w * max_w {
        st.w *= max_w / wl2.sqrt();
        b.capped |= CAPPED_ANGULAR;
    }
}

/// Moves every body by its substep velocity, clamped to the speed caps first (the solve may
/// have raised it past them). Bodies with an anisotropic inertia and no rotation lock turn by
/// the implicit midpoint rule ([`free_rotation_step`]), which keeps the energy and the
/// angular momentum of free rotation; the others by the first-order quaternion update.
/// Returns how many midpoint solves missed their tolerance.
fn integrate_positions(
    bodies: &mut [SolverBody],
    states: &mut [BodyState],
    h: f32,
    p: &SolveParams,
) -> u32 {
    let mut not_converged = 0;
    for (b, st) in bodies.iter_mut().zip(states.iter_mut()).skip(1) {
        clamp_to_caps(b, st, p.max_linear_speed, p.max_angular_speed);
        st.dp += st.v * h;
        let w = st.w;
        if w == Vec3A::ZERO {
            continue;
        }
        let dq = b.dq;
        if b.gyro {
            let q_old = dq * b.q0;
            let omega = if w == b.omega_world {
                b.omega_body
            } else {
                rotate(q_old.inverse(), Vec3::from(w))
            };
            let step = free_rotation_step(b.inertia_local, omega, h);
            not_converged += u32::from(!step.converged);
            let q_new = q_old * step.rotation;
            b.dq = unit_rotation(q_new * b.q0.inverse());
            st.dtheta += q_old * step.rotation_vector;
            let omega = Vec3::from(step.omega);
            st.w = Vec3A::from(rotate(q_new, omega)) * b.ang_mask;
            b.omega_body = omega;
            b.omega_world = st.w;
            continue;
        }
        st.dtheta += w * h;
        let spin = Quat::from_xyzw(w.x, w.y, w.z, 0.0) * dq;
        b.dq = unit_rotation(Quat::from_xyzw(
            dq.x + 0.5 * h * spin.x,
            dq.y + 0.5 * h * spin.y,
            dq.z + 0.5 * h * spin.z,
            dq.w + 0.5 * h * spin.w,
        ));
    }
    not_converged
}

/// `q * v` with the length of `v` kept exactly: a unit quaternion in f32 has a norm off by
/// rounding, and the two frame changes per substep of a tumbling body would otherwise scale
/// its spin by that error every substep (energy drifted by 0.6 % per minute at 240 Hz).
#[inline]
fn rotate(q: Quat, v: Vec3) -> Vec3 {
    let r = q * v;
    let (l2, r2) = (v.length_squared(), r.length_squared());
    if r2 > 0.0 {
        r * (l2 / r2).sqrt()
    } else {
        r
    }
}
