//! `ElasticEnergy`: the energy of each group of bodies that only elastic contacts pushed
//! in a step, projected back onto its value at the step's start by scaling the step's
//! restitution impulses (a projection onto an invariant, as in Hairer, Lubich & Wanner,
//! *Geometric Numerical Integration*, §IV.4).
//!
//! Frictionless contacts with `e = 1` do no work over an impact, so gravity and forces are
//! all that change such a group's energy, and the integrator keeps that exactly (see
//! [`shadow_energy`]). The restitution passes (see [`super::restitution`]) return each
//! impact's energy at the contact, measured along its normal. Where one body meets two others
//! in one step, the positions the soft substeps leave do not match any sequence of rigid
//! impacts: a ball near the apex of a small hop on the floor, struck from above, is held by
//! the floor in the air, and the ball that struck it leaves from where the substeps stopped
//! it, lower than its rebound would have carried it. Each such step lost or gained up to
//! 0.2 % of the energy of 50 elastic balls in a box at 30 Hz, most often lost: they lost 8 %
//! of it over 10,000 steps under gravity; projected, they keep it within 0.6 %
//! (`tests/restitution.rs`).
//!
//! The projection keeps the impulses' directions and their balance between bodies (so
//! momentum between the group's bodies is kept) and scales their size by one factor `k`,
//! within [`SCALE_RANGE`]. It runs only where the law is exact: every contact that pushed a
//! body of the group is elastic, no joint, damping, torque, speed cap or moving kinematic
//! body touches it, and an impact reached it this step.

use glam::{Mat3, Vec3A};

use super::batching::ContactBatches;
use super::body_state::BodyState;
use super::joint_constraint::JointConstraint;
use super::solver_body::SolverBody;
use crate::pipeline::union_find::UnionFind;

/// The factor on a group's restitution impulses stays within `1 / 1.5 ..= 1.5`: a group
/// that needs more is moved only that far towards its energy. Among 50 equal elastic balls
/// it ranged over 0.73–1.12 (99 % of 570,000 groups, at every preset, within
/// 0.9999–1.0006). A box spinning at 30–40 rad/s at 30 Hz turns a radian within a step, and
/// the contact's rebound at the step's end gave it 12–30 % too much energy, beyond any
/// small correction (a box dropped tilted from 2.5 m gained 40 % over 20 s at fast left as
/// it was, 12 % moved to the range's edge; 2.1× before the projection).
pub const SCALE_RANGE: (f32, f32) = (1.0 / 1.5, 1.5);

/// Linear and angular velocity of a body.
type Velocity = (Vec3A, Vec3A);

/// The conserved energy of semi-implicit Euler with steps of `h` under a constant
/// acceleration `a`, J: `½·m·v² − m·a·x + ½·m·h·a·v` (the kinetic energy with the rotation's,
/// `½·ωᵀIω`). With `v′ = v + a·h`, `x′ = x + v′·h` it is exact: the plain `½·m·v² − m·a·x`
/// falls by `½·m·a²·h²` a step in free fall. `dp` is the displacement from where the
/// potential is measured.
#[must_use]
#[allow(clippy::too_many_arguments)]
pub fn shadow_energy(
    m: f32,
    inertia: Mat3,
    a: Vec3A,
    h: f32,
    v: Vec3A,
    w: Vec3A,
    dp: Vec3A,
) -> f32 {
    0.5 * m * v.length_squared() + 0.5 * w.dot(times(inertia, w)) - m * a.dot(dp)
        + 0.5 * m * h * a.dot(v)
}

/// The factor `k` on the impulses for which `c + b·k + a·k² = target` (a group's energy
/// with its restitution impulses scaled by `k`), the root nearest 1; where none is real (the
/// energy is above the target for every `k`), the `k` of least energy; clamped to
/// [`SCALE_RANGE`] (between 1 and the root the energy lies between its value at 1 and the
/// target: the clamped `k` moves it towards the target, never past). `None` where the
/// impulses change nothing (`a ≤ 0`) or a sum is not finite.
#[must_use]
pub fn impulse_scale(a: f64, b: f64, c: f64, target: f64) -> Option<f32> {
    if a <= 0.0 || !(a.is_finite() && b.is_finite() && c.is_finite() && target.is_finite()) {
        return None;
    }
    let disc = b * b - 4.0 * a * (c - target);
    let k = if disc >= 0.0 {
        let r = disc.sqrt();
        let (k1, k2) = ((-b + r) / (2.0 * a), (-b - r) / (2.0 * a));
        if (k1 - 1.0).abs() <= (k2 - 1.0).abs() {
            k1
        } else {
            k2
        }
    } else {
        -b / (2.0 * a)
    } as f32;
    Some(k.clamp(SCALE_RANGE.0, SCALE_RANGE.1))
}

/// Per group of bodies (by union-find root): whether the law holds, whether an impact
/// reached it, and the sums of [`impulse_scale`] (`a`, `b`, `c`, target).
#[derive(Clone, Copy, Debug, Default)]
struct Group {
    spoilt: bool,
    struck: bool,
    sums: [f64; 4],
}

/// The projection's inputs gathered during a step and its scratch, kept between steps (see
/// the module docs).
#[derive(Debug, Default)]
pub(crate) struct ElasticEnergy {
    /// Per solver body, the direction into the supports that hold it (see
    /// `RestingAccelerations::pressing_of`), or zero; filled by the solve stage.
    pub pressing: Vec<Vec3A>,
    /// Velocities at step start.
    start: Vec<Velocity>,
    /// Velocities before the restitution passes.
    before: Vec<Velocity>,
    /// Per body: something that does work touches it (by body, then by group).
    spoilt: Vec<bool>,
    groups: UnionFind,
    group: Vec<Group>,
}

impl ElasticEnergy {
    /// Records the velocities at step start.
    pub(crate) fn record_start(&mut self, states: &[BodyState]) {
        self.start.clear();
        self.start.extend(states.iter().map(|s| (s.v, s.w)));
    }

    /// Records the velocities before the restitution passes.
    pub(crate) fn record_before(&mut self, states: &[BodyState]) {
        self.before.clear();
        self.before.extend(states.iter().map(|s| (s.v, s.w)));
    }

    /// Projects the energy of each group of bodies that only elastic contacts pushed this
    /// step, and that an impact reached (`struck`), back onto its energy at step start (see
    /// the module docs); `states` holds the velocities after the restitution passes.
    pub(crate) fn project(
        &mut self,
        bodies: &[SolverBody],
        states: &mut [BodyState],
        struck: &[bool],
        batches: &ContactBatches,
        joints: &[JointConstraint],
        h: f32,
    ) {
        let n = states.len();
        if !struck.iter().any(|&s| s) || self.start.len() != n || self.before.len() != n {
            return;
        }
        let Self {
            pressing,
            start,
            before,
            spoilt,
            groups,
            group,
        } = self;
        groups.reset(n);
        spoilt.clear();
        spoilt.resize(n, false);
        batches.for_each_pushing_link(|link| {
            let [a, b] = link.bodies;
            if link.writes == [true, true] {
                groups.union(a, b);
            }
            let moving = link.bodies.iter().zip(link.writes).any(|(&body, writes)| {
                let st = &states[body as usize];
                !writes && (st.v != Vec3A::ZERO || st.w != Vec3A::ZERO)
            });
            if !link.elastic || moving {
                spoilt[a as usize] = true;
                spoilt[b as usize] = true;
            }
        });
        for j in joints {
            if j.writes == 3 {
                groups.union(j.body_a, j.body_b);
            }
            spoilt[j.body_a as usize] = true;
            spoilt[j.body_b as usize] = true;
        }
        group.clear();
        group.resize(n, Group::default());
        for (i, b) in bodies.iter().enumerate().skip(1) {
            let g = &mut group[groups.find(i as u32) as usize];
            g.spoilt |= spoilt[i]
                || b.lin_damp_factor != 1.0
                || b.ang_damp_factor != 1.0
                || b.ang_acc != Vec3A::ZERO
                || b.capped != 0;
            g.struck |= struck[i];
        }
        let applies = |g: &Group| g.struck && !g.spoilt;
        for i in 1..n {
            let st = &states[i];
            let inv = st.inv_mass.max_element();
            let root = groups.find(i as u32) as usize;
            if inv <= 0.0 || !applies(&group[root]) {
                continue;
            }
            let b = &bodies[i];
            let m = 1.0 / inv;
            let acc = b.lin_acc * b.lin_mask;
            let (v0, w0) = start[i];
            let (vb, wb) = before[i];
            let (dv, dw) = (st.v - vb, st.w - wb);
            let spins = w0 != Vec3A::ZERO || st.w != Vec3A::ZERO || wb != Vec3A::ZERO;
            let (i0, i1) = if spins {
                (world_inertia(b, b.q0), world_inertia(b, b.dq * b.q0))
            } else {
                (Mat3::ZERO, Mat3::ZERO)
            };
            // A body held by its supports counts where it started along the direction it is
            // pressed into them: the impact pressed it into the soft contact, which pushes it
            // back out over the next steps (a ball lying on the floor, struck from above,
            // sank 5 mm at 30 Hz; counted, its rebound was given that potential energy
            // twice).
            let p = pressing.get(i).copied().unwrap_or(Vec3A::ZERO);
            let dp = st.dp - p * st.dp.dot(p).max(0.0);
            let s = &mut group[root].sums;
            s[0] += f64::from(0.5 * m * dv.length_squared() + 0.5 * dw.dot(times(i1, dw)));
            s[1] += f64::from(m * vb.dot(dv) + dw.dot(times(i1, wb)) + 0.5 * m * h * acc.dot(dv));
            s[2] += f64::from(shadow_energy(m, i1, acc, h, vb, wb, dp));
            s[3] += f64::from(shadow_energy(m, i0, acc, h, v0, w0, Vec3A::ZERO));
        }
        for i in 1..n {
            let g = &group[groups.find(i as u32) as usize];
            if !applies(g) {
                continue;
            }
            let [a, b, c, target] = g.sums;
            // Solved per body from its group's sums: cheap next to the sums themselves.
            if let Some(k) = impulse_scale(a, b, c, target) {
                let (vb, wb) = before[i];
                let st = &mut states[i];
                st.v = vb + (st.v - vb) * k;
                st.w = wb + (st.w - wb) * k;
            }
        }
    }
}

/// `R·I·Rᵀ`: a body's inertia in the world at rotation `q`.
fn world_inertia(b: &SolverBody, q: glam::Quat) -> Mat3 {
    let r = Mat3::from_quat(q);
    r * b.inertia_local * r.transpose()
}

/// `m·x` for a 3×3 matrix and a SIMD vector.
fn times(m: Mat3, x: Vec3A) -> Vec3A {
    Vec3A::from(m * glam::Vec3::from(x))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shadow_energy_of_free_fall_is_kept_exactly() {
        let (m, h) = (2.0f32, 1.0 / 60.0);
        let a = Vec3A::new(0.0, -9.81, 0.0);
        let (mut v, mut x) = (Vec3A::new(1.0, 3.0, 0.0), Vec3A::ZERO);
        let e0 = shadow_energy(m, Mat3::IDENTITY, a, h, v, Vec3A::ZERO, x);
        for _ in 0..120 {
            v += a * h;
            x += v * h;
        }
        let e1 = shadow_energy(m, Mat3::IDENTITY, a, h, v, Vec3A::ZERO, x);
        assert!((e1 - e0).abs() < 1e-4 * e0.abs(), "{e0} → {e1}");
    }

    #[test]
    fn the_scale_nearest_one_restores_the_target() {
        // One body: 1 kg, before the impulses at rest, after at 2 m/s: E(k) = 2·k².
        let k = impulse_scale(2.0, 0.0, 0.0, 2.42).expect("a root");
        assert!((k - 1.1).abs() < 1e-6, "{k}");
        // Already right: 1.
        assert_eq!(impulse_scale(2.0, 0.0, 0.0, 2.0), Some(1.0));
        // Out of range: as far as the range goes (k = 2 wanted); nothing to scale: none.
        assert_eq!(impulse_scale(2.0, 0.0, 0.0, 8.0), Some(SCALE_RANGE.1));
        assert_eq!(impulse_scale(0.0, 0.0, 0.0, 1.0), None);
        assert_eq!(impulse_scale(2.0, f64::NAN, 0.0, 1.0), None);
        // Above the target for every k: the least energy, if in range.
        // E(k) = 1 − 2k + k² + 0.5 has its least, 0.5, at k = 1.
        assert_eq!(impulse_scale(1.0, -2.0, 1.5, 0.2), Some(1.0));
    }
}
