//! [`solve_substeps`]: the soft-step loop (integrate velocities → warm start → solve →
//! integrate positions → relax, per substep; restitution at the end).

use glam::{Quat, Vec3, Vec3A};

use super::batching::ContactBatches;
use super::body_state::BodyState;
use super::contact_batch::Pass;
use super::solver_body::SolverBody;
use crate::pose::unit_rotation;

/// Parameters of one solver run (derived from `PhysicsSettings`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SolveParams {
    pub dt: f32,
    pub substeps: u32,
    pub iterations: u32,
    pub relax_iterations: u32,
    pub max_push: f32,
    pub restitution_threshold: f32,
    pub max_linear_speed: f32,
    pub max_angular_speed: f32,
}

/// Runs all substeps over awake bodies and their contact batches.
pub(crate) fn solve_substeps(
    bodies: &mut [SolverBody],
    states: &mut [BodyState],
    batches: &mut ContactBatches,
    p: &SolveParams,
) {
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
    for _ in 0..substeps {
        integrate_velocities(bodies, states, h, p);
        batches.warm_start(states);
        for _ in 0..p.iterations.max(1) {
            batches.solve(states, solve_pass);
        }
        integrate_positions(bodies, states, h);
        for _ in 0..p.relax_iterations {
            batches.solve(states, relax_pass);
        }
    }
    batches.apply_restitution(states, p.restitution_threshold);
}

fn integrate_velocities(bodies: &[SolverBody], states: &mut [BodyState], h: f32, p: &SolveParams) {
    let max_v2 = p.max_linear_speed * p.max_linear_speed;
    let max_w2 = p.max_angular_speed * p.max_angular_speed;
    for (b, st) in bodies.iter().zip(states.iter_mut()).skip(1) {
        let mut v = st.v + b.lin_acc * h;
        let mut w = st.w + b.ang_acc * h;
        v *= b.lin_damp_factor;
        w *= b.ang_damp_factor;
        // Squared lengths against squared limits: no square root for the common case.
        let vl2 = v.length_squared();
        if vl2 > max_v2 {
            v *= p.max_linear_speed / vl2.sqrt();
        }
        let wl2 = w.length_squared();
        if wl2 > max_w2 {
            w *= p.max_angular_speed / wl2.sqrt();
        }
        st.v = v * b.lin_mask;
        st.w = w * b.ang_mask;
    }
}

fn integrate_positions(bodies: &mut [SolverBody], states: &mut [BodyState], h: f32) {
    for (b, st) in bodies.iter_mut().zip(states.iter_mut()).skip(1) {
        st.dp += st.v * h;
        st.dtheta += st.w * h;
        let w = st.w;
        if w == Vec3A::ZERO {
            continue;
        }
        let q_old = b.dq * b.q0;
        let dq = b.dq;
        let spin = Quat::from_xyzw(w.x, w.y, w.z, 0.0) * dq;
        b.dq = unit_rotation(Quat::from_xyzw(
            dq.x + 0.5 * h * spin.x,
            dq.y + 0.5 * h * spin.y,
            dq.z + 0.5 * h * spin.z,
            dq.w + 0.5 * h * spin.w,
        ));
        if b.gyro {
            // Free rotation keeps world angular momentum L = R I Rᵀ ω.
            let q_new = b.dq * b.q0;
            let l = q_old * (b.inertia_local * (q_old.inverse() * Vec3::from(w)));
            st.w = Vec3A::from(q_new * (b.inv_inertia_local * (q_new.inverse() * l))) * b.ang_mask;
        }
    }
}
