//! [`RestingAccelerations`]: the acceleration each awake body has with the bodies it rests
//! on, for the impact speed of restitution (see [`crate::solver::restitution`]).
//!
//! A body's own acceleration (gravity, forces) is not what brings a falling body onto it
//! when it rests on something: a ball lying on the floor does not fall, and a ball landing
//! on it closes the gap under the full `g`. Taken as falling too, the two closed at their
//! step-start speed, the rebound lacked the speed gained over the last gap: the upper ball of
//! a column of two elastic balls rose to 82 % of its drop at 30 Hz. A contact's own impact
//! sees the bodies' accelerations without the support it gives itself.

use glam::Vec3;

use crate::narrowphase::contact_pair::ContactPair;
use crate::solver::body_state::BodyState;
use crate::solver::contact_constraint::ManifoldRef;
use crate::solver::solver_body::SolverBody;

/// Sweeps over the manifolds that pass support one body further up a stack; a taller stack
/// keeps its upper bodies' own accelerations (their rebounds are then short of the gap's
/// speed, never past it).
const MAX_SWEEPS: usize = 8;

/// Per solver body, its own acceleration and that less the part pressing it into the
/// bodies it rests on, each held in turn (by a static or kinematic body, or by one held).
#[derive(Debug, Default)]
pub(crate) struct RestingAccelerations {
    own: Vec<Vec3>,
    resting: Vec<Vec3>,
}

impl RestingAccelerations {
    /// Resting: a manifold within `slop` of touching whose bodies move apart or together no
    /// faster than their relative acceleration along its normal over one step of `dt`.
    /// Marks in each manifold's `rests` which of its bodies rest on the other through it.
    pub(crate) fn new(
        refs: &mut [ManifoldRef],
        pairs: &[ContactPair],
        bodies: &[SolverBody],
        states: &[BodyState],
        slop: f32,
        dt: f32,
    ) -> Self {
        let own: Vec<Vec3> = bodies.iter().map(|b| Vec3::from(b.lin_acc)).collect();
        let mut accel = own.clone();
        let mut held = vec![false; bodies.len()];
        let resting: Vec<(usize, Vec3)> = refs
            .iter()
            .enumerate()
            .filter_map(|(i, r)| {
                let m = &pairs[r.pair as usize].manifolds[r.manifold as usize];
                let (a, b) = (r.body_a as usize, r.body_b as usize);
                let n = m.normal;
                let apart = n.dot(Vec3::from(states[b].v - states[a].v));
                let closing = n.dot(own[b] - own[a]).abs() * dt;
                (m.min_separation() <= slop && apart.abs() <= closing).then_some((i, n))
            })
            .collect();
        for _ in 0..MAX_SWEEPS {
            let mut changed = false;
            for &(i, n) in &resting {
                let r = &mut refs[i];
                if r.rests != 0 {
                    continue;
                }
                let (a, b) = (r.body_a as usize, r.body_b as usize);
                let a_fixed = r.writes & 1 == 0 || held[a];
                let b_fixed = r.writes & 2 == 0 || held[b];
                // B on A: B's acceleration presses it into A (along −n); or A on B.
                let (body, n, bit) = if r.writes & 2 != 0 && a_fixed && accel[b].dot(n) < 0.0 {
                    (b, n, 2)
                } else if r.writes & 1 != 0 && b_fixed && accel[a].dot(n) > 0.0 {
                    (a, -n, 1)
                } else {
                    continue;
                };
                let pressing = accel[body].dot(n) * n;
                accel[body] -= pressing;
                held[body] = true;
                r.rests = bit;
                changed = true;
            }
            if !changed {
                break;
            }
        }
        Self {
            own,
            resting: accel,
        }
    }

    /// Where side `side` (0: A, 1: B) of manifold `r` is held by supports of its own, not
    /// through `r` (a ball lying on the floor, for a ball landing on it): the unit direction
    /// its acceleration presses it into them, the part its supports take (its own less its
    /// resting acceleration); else zero (nothing was taken).
    pub(crate) fn pressing(&self, r: &ManifoldRef, side: u8) -> Vec3 {
        if r.rests & (1 << side) != 0 {
            return Vec3::ZERO;
        }
        self.pressing_of(side_body(r, side))
    }

    /// Where solver body `body` is held by supports, the unit direction its acceleration
    /// presses it into them; else zero.
    pub(crate) fn pressing_of(&self, body: usize) -> Vec3 {
        match (self.own.get(body), self.resting.get(body)) {
            (Some(&own), Some(&resting)) => (own - resting).normalize_or_zero(),
            _ => Vec3::ZERO,
        }
    }

    /// The acceleration, m/s², of side `side` (0: A, 1: B) of manifold `r` for its impact:
    /// with its supports, unless it rests on the other body through `r` itself (then its
    /// own: the support `r` gives is what the impact is about).
    pub(crate) fn get(&self, r: &ManifoldRef, side: u8) -> Vec3 {
        let body = side_body(r, side);
        let list = if r.rests & (1 << side) != 0 {
            &self.own
        } else {
            &self.resting
        };
        list.get(body).copied().unwrap_or(Vec3::ZERO)
    }
}

/// The solver slot of side `side` (0: A, 1: B) of manifold `r`.
fn side_body(r: &ManifoldRef, side: u8) -> usize {
    (if side == 0 { r.body_a } else { r.body_b }) as usize
}
