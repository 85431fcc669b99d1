//! [`ContactBatches`]: the step's contact constraints dealt into [`ContactBatch`]es of four
//! with no dynamic body twice in one batch (greedy graph colouring, as in Box2D v3), so that
//! four manifolds are solved at once without racing on a body.

use super::body_state::BodyState;
use super::contact_batch::ContactBatch;
use super::contact_constraint::{ConstraintPoint, ContactConstraint};
use super::lanes::LANES;

/// Colours per round: one bit each in a body's mask. Constraints that find no free colour (a
/// body with more than this many contacts) wait for the next round.
const COLORS: usize = 64;

/// The batches of one step, in solve order, and the scratch that builds them.
#[derive(Debug, Default)]
pub(crate) struct ContactBatches {
    /// Manifolds laid out for four points (faces; two- and three-point manifolds too).
    pub four: Vec<ContactBatch<4>>,
    /// One-point manifolds (spheres, capsule ends, vertex contacts).
    pub one: Vec<ContactBatch<1>>,
    /// Colours already used by each solver body in this round.
    colors_of_body: Vec<u64>,
    /// Constraint indices per colour and layout (`2·colour + (four-point ? 1 : 0)`).
    buckets: Vec<Vec<u32>>,
    pending: Vec<u32>,
    deferred: Vec<u32>,
}

impl ContactBatches {
    /// Colours `constraints` and packs them. Order is deterministic: colours in order,
    /// constraints in their order within a colour.
    pub(crate) fn build(
        &mut self,
        constraints: &[ContactConstraint],
        points: &[ConstraintPoint],
        states: &[BodyState],
    ) {
        self.four.clear();
        self.one.clear();
        self.buckets.resize_with(2 * COLORS, Vec::new);
        self.pending.clear();
        self.pending.extend(0..constraints.len() as u32);
        while !self.pending.is_empty() {
            self.colors_of_body.clear();
            self.colors_of_body.resize(states.len(), 0);
            for &ci in &self.pending {
                let c = &constraints[ci as usize];
                let (a, b) = (c.body_a as usize, c.body_b as usize);
                let writes_a = c.writes & 1 != 0;
                let writes_b = c.writes & 2 != 0;
                let used = if writes_a { self.colors_of_body[a] } else { 0 }
                    | if writes_b { self.colors_of_body[b] } else { 0 };
                if used == u64::MAX {
                    self.deferred.push(ci);
                    continue;
                }
                let color = (!used).trailing_zeros() as usize;
                if writes_a {
                    self.colors_of_body[a] |= 1 << color;
                }
                if writes_b {
                    self.colors_of_body[b] |= 1 << color;
                }
                let layout = usize::from(c.count > 1);
                self.buckets[2 * color + layout].push(ci);
            }
            for (slot, bucket) in self.buckets.iter_mut().enumerate() {
                for lanes in bucket.chunks(LANES) {
                    if slot % 2 == 1 {
                        self.four
                            .push(ContactBatch::pack(lanes, constraints, points, states));
                    } else {
                        self.one
                            .push(ContactBatch::pack(lanes, constraints, points, states));
                    }
                }
                bucket.clear();
            }
            std::mem::swap(&mut self.pending, &mut self.deferred);
            self.deferred.clear();
        }
    }

    /// Writes every batch's impulses back to the constraints and their points.
    pub(crate) fn unpack(
        &self,
        constraints: &mut [ContactConstraint],
        points: &mut [ConstraintPoint],
    ) {
        for b in &self.four {
            b.unpack(constraints, points);
        }
        for b in &self.one {
            b.unpack(constraints, points);
        }
    }
}

#[cfg(test)]
mod tests {
    use glam::Vec3A;

    use super::*;
    use crate::solver::contact_constraint::{FrictionPart, NormalBlock};
    use crate::solver::Softness;

    fn constraint(body_a: u32, body_b: u32, writes: u8, count: u8) -> ContactConstraint {
        ContactConstraint {
            body_a,
            body_b,
            writes,
            normal: Vec3A::Y,
            tangent: [Vec3A::X, Vec3A::Z],
            restitution: 0.0,
            softness: Softness::RIGID,
            first: 0,
            count,
            pair: 0,
            manifold: 0,
            friction: FrictionPart::default(),
            block: NormalBlock::default(),
        }
    }

    /// Every constraint lands in exactly one lane of one batch of its layout, and no batch
    /// has a written body twice — also for a body with more contacts than colours.
    #[test]
    fn every_constraint_once_and_no_written_body_twice_in_a_batch() {
        let bodies = 80u32;
        let mut constraints = Vec::new();
        // A chain (each body touches the next), all on the static ground (index 0, never
        // written), and a hub, body 1, touching every other body: 79 contacts, more than
        // the 64 colours of one round.
        for b in 2..bodies {
            constraints.push(constraint(b - 1, b, 3, 4));
            constraints.push(constraint(0, b, 2, 1));
            constraints.push(constraint(1, b, 3, if b % 2 == 0 { 1 } else { 3 }));
        }
        let points = vec![ConstraintPoint::default(); 4];
        let states = vec![BodyState::STATIC; bodies as usize];
        let mut batches = ContactBatches::default();
        batches.build(&constraints, &points, &states);

        let mut seen = vec![0u32; constraints.len()];
        let mut check = |lanes: &[u32; LANES], four: bool| {
            let mut written = Vec::new();
            for &ci in lanes.iter().filter(|&&ci| ci != u32::MAX) {
                seen[ci as usize] += 1;
                let c = &constraints[ci as usize];
                assert_eq!(c.count > 1, four, "constraint {ci} in the wrong layout");
                for (bit, body) in [(1u8, c.body_a), (2, c.body_b)] {
                    if c.writes & bit != 0 {
                        assert!(!written.contains(&body), "body {body} twice in {lanes:?}");
                        written.push(body);
                    }
                }
            }
        };
        batches.four.iter().for_each(|b| check(&b.constraint, true));
        batches.one.iter().for_each(|b| check(&b.constraint, false));
        assert!(seen.iter().all(|&n| n == 1), "{seen:?}");
    }
}
