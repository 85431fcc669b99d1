//! [`ContactBatches`]: the step's contact constraints dealt into [`ContactBatch`]es of four
//! with no dynamic body twice in one batch, so that four manifolds are solved at once without
//! racing on a body, in about the order the constraints come in.
//!
//! Order matters to a Gauss–Seidel sweep: one pass carries a load along a chain of contacts
//! as far as the chain follows the order. Graph colouring (Box2D v3) solves a colour at a
//! time across the whole scene, so a pass carries a pile's weight down only a few contacts,
//! and the 8,000 poured spheres sank 3.3 cm instead of 2.3 cm. Here each constraint joins
//! the oldest of a few open batches that does not write its bodies yet, and a batch is solved
//! in the order it fills: the sweep follows the constraints' order within a few places.

use super::body_state::BodyState;
use super::column_solve::ColumnSolve;
use super::contact_batch::{
    ContactBatch, FaceBatch, Jitter, LaneResult, Levers, LinearFaceBatch, LinearPointBatch, Link,
    ManifoldRows, Pass, PointBatch,
};
use super::contact_constraint::{ManifoldRef, PreparedManifold};
use super::lanes::LANES;

/// Batch kinds, in solve order: angular faces, angular points, linear faces, linear points.
const LAYOUTS: usize = 4;

/// The batch kind of a manifold (an index into [`ContactBatches::open`]).
fn layout(r: &ManifoldRef) -> usize {
    usize::from(r.count <= 1) | usize::from(!r.angular) << 1
}

/// Batches being filled at once, per layout. More finds a free lane more often (fuller
/// batches), fewer keeps closer to the constraints' order.
const OPEN_BATCHES: usize = 8;

/// A batch being filled: its constraints and the bodies they write.
#[derive(Clone, Copy, Debug)]
struct OpenBatch {
    lanes: [u32; LANES],
    len: usize,
    written: [u32; 2 * LANES],
    written_len: usize,
}

impl OpenBatch {
    const EMPTY: Self = Self {
        lanes: [u32::MAX; LANES],
        len: 0,
        written: [0; 2 * LANES],
        written_len: 0,
    };

    fn writes_any(&self, bodies: &[u32]) -> bool {
        self.written[..self.written_len]
            .iter()
            .any(|w| bodies.contains(w))
    }

    fn push(&mut self, ci: u32, bodies: &[u32]) {
        self.lanes[self.len] = ci;
        self.len += 1;
        for &b in bodies {
            self.written[self.written_len] = b;
            self.written_len += 1;
        }
    }
}

/// The batches of one step, in solve order, and the scratch that builds them.
#[derive(Debug, Default)]
pub(crate) struct ContactBatches {
    /// Manifolds laid out for four points (faces; two- and three-point manifolds too).
    pub four: Vec<FaceBatch>,
    /// One-point manifolds (spheres, capsule ends, vertex contacts).
    pub one: Vec<PointBatch>,
    /// Manifolds of several points between bodies that do not rotate.
    pub four_linear: Vec<LinearFaceBatch>,
    /// One-point manifolds between bodies that do not rotate.
    pub one_linear: Vec<LinearPointBatch>,
    /// Batches being filled, oldest first, per layout (see [`layout`]).
    open: [Vec<OpenBatch>; LAYOUTS],
    /// The column faces among the batches, grouped by column (see [`ColumnSolve`]).
    columns: ColumnSolve,
}

/// Packs the lanes of one batch at the end of `out`, preparing each manifold in `scratch`
/// (reused: a prepared manifold is larger than a lane, and copying one out per manifold
/// showed in the pyramid's profile).
fn pack<const N: usize, M: ManifoldRows, L: Levers<N>>(
    out: &mut Vec<ContactBatch<N, M, L>>,
    lanes: &[u32],
    manifolds: &[ManifoldRef],
    states: &[BodyState],
    prepare: &mut impl FnMut(&ManifoldRef, &mut PreparedManifold),
    scratch: &mut PreparedManifold,
) {
    out.push(ContactBatch::EMPTY);
    if let Some(b) = out.last_mut() {
        for (l, &id) in lanes.iter().enumerate() {
            prepare(&manifolds[id as usize], scratch);
            b.set_lane(l, id, scratch, states);
        }
    }
}

impl ContactBatches {
    /// Deals `manifolds` into batches, preparing each one (`prepare` fills the
    /// `PreparedManifold` it is given: the constraint, and the first `count` points) as its
    /// batch is packed. Deterministic: it depends only on the manifolds and their order. Lanes report
    /// their index in `manifolds`.
    pub(crate) fn build(
        &mut self,
        manifolds: &[ManifoldRef],
        states: &[BodyState],
        mut prepare: impl FnMut(&ManifoldRef, &mut PreparedManifold),
    ) {
        let scratch = &mut PreparedManifold::default();
        self.four.clear();
        self.one.clear();
        self.four_linear.clear();
        self.one_linear.clear();
        for (i, r) in manifolds.iter().enumerate() {
            let layout = layout(r);
            let mut bodies = [0u32; 2];
            let mut n = 0;
            if r.writes & 1 != 0 {
                bodies[n] = r.body_a;
                n += 1;
            }
            if r.writes & 2 != 0 {
                bodies[n] = r.body_b;
                n += 1;
            }
            let bodies = &bodies[..n];
            let open = &mut self.open[layout];
            let slot = match open.iter().position(|b| !b.writes_any(bodies)) {
                Some(slot) => slot,
                None => {
                    if open.len() == OPEN_BATCHES {
                        let oldest = open.remove(0);
                        self.emit(layout, &oldest, manifolds, states, &mut prepare, scratch);
                    }
                    let open = &mut self.open[layout];
                    open.push(OpenBatch::EMPTY);
                    open.len() - 1
                }
            };
            let open = &mut self.open[layout];
            open[slot].push(i as u32, bodies);
            if open[slot].len == LANES {
                let full = open.remove(slot);
                self.emit(layout, &full, manifolds, states, &mut prepare, scratch);
            }
        }
        for layout in 0..LAYOUTS {
            let open = std::mem::take(&mut self.open[layout]);
            for b in &open {
                self.emit(layout, b, manifolds, states, &mut prepare, scratch);
            }
            self.open[layout] = open;
            self.open[layout].clear();
        }
        self.columns.build(&self.four, &self.four_linear);
    }

    fn emit(
        &mut self,
        layout: usize,
        batch: &OpenBatch,
        manifolds: &[ManifoldRef],
        states: &[BodyState],
        prepare: &mut impl FnMut(&ManifoldRef, &mut PreparedManifold),
        scratch: &mut PreparedManifold,
    ) {
        let lanes = &batch.lanes[..batch.len];
        match layout {
            0 => pack(&mut self.four, lanes, manifolds, states, prepare, scratch),
            1 => pack(&mut self.one, lanes, manifolds, states, prepare, scratch),
            2 => pack(
                &mut self.four_linear,
                lanes,
                manifolds,
                states,
                prepare,
                scratch,
            ),
            _ => pack(
                &mut self.one_linear,
                lanes,
                manifolds,
                states,
                prepare,
                scratch,
            ),
        }
    }

    /// Re-applies last step's impulses, batch by batch.
    pub(crate) fn warm_start(&self, states: &mut [BodyState]) {
        self.four.iter().for_each(|b| b.warm_start(states));
        self.one.iter().for_each(|b| b.warm_start(states));
        self.four_linear.iter().for_each(|b| b.warm_start(states));
        self.one_linear.iter().for_each(|b| b.warm_start(states));
    }

    /// One Gauss–Seidel pass over every batch.
    pub(crate) fn solve(&mut self, states: &mut [BodyState], pass: Pass) {
        self.four.iter_mut().for_each(|b| b.solve(states, pass));
        self.one.iter_mut().for_each(|b| b.solve(states, pass));
        self.four_linear
            .iter_mut()
            .for_each(|b| b.solve(states, pass));
        self.one_linear
            .iter_mut()
            .for_each(|b| b.solve(states, pass));
    }

    /// Whether some batch holds a column face (`ContactConstraint::column`).
    pub(crate) fn has_columns(&self) -> bool {
        !self.columns.is_empty()
    }

    /// One coarse correction of the columns (see [`ColumnSolve::correct`]).
    pub(crate) fn correct_columns(&mut self, states: &mut [BodyState], pass: Pass) {
        self.columns
            .correct(&mut self.four, &mut self.four_linear, states, pass);
    }

    /// One more pass over the batches that hold a column face (their other lanes too: a
    /// pass is per batch).
    pub(crate) fn solve_columns(&mut self, states: &mut [BodyState], pass: Pass) {
        for b in self.four.iter_mut().filter(|b| b.has_column()) {
            b.solve(states, pass);
        }
        for b in self.four_linear.iter_mut().filter(|b| b.has_column()) {
            b.solve(states, pass);
        }
    }

    /// One restitution pass after the substeps, batch by batch (see
    /// [`ContactBatch::apply_restitution`](super::contact_batch::ContactBatch::apply_restitution));
    /// returns the largest change of a point's normal velocity it made, m/s.
    pub(crate) fn apply_restitution(
        &mut self,
        states: &mut [BodyState],
        struck: &mut [bool],
        h: f32,
        jitter: Jitter,
    ) -> f32 {
        let mut change = 0.0f32;
        for b in &mut self.four {
            change = change.max(b.apply_restitution(states, struck, h, jitter));
        }
        for b in &mut self.one {
            change = change.max(b.apply_restitution(states, struck, h, jitter));
        }
        for b in &mut self.four_linear {
            change = change.max(b.apply_restitution(states, struck, h, jitter));
        }
        for b in &mut self.one_linear {
            change = change.max(b.apply_restitution(states, struck, h, jitter));
        }
        change
    }

    /// Calls `f` for every manifold that pushed this step (see
    /// [`ContactBatch::for_each_pushing_link`](super::contact_batch::ContactBatch::for_each_pushing_link)).
    pub(crate) fn for_each_pushing_link(&self, mut f: impl FnMut(Link)) {
        self.four
            .iter()
            .for_each(|b| b.for_each_pushing_link(&mut f));
        self.one
            .iter()
            .for_each(|b| b.for_each_pushing_link(&mut f));
        self.four_linear
            .iter()
            .for_each(|b| b.for_each_pushing_link(&mut f));
        self.one_linear
            .iter()
            .for_each(|b| b.for_each_pushing_link(&mut f));
    }

    /// Calls `f(manifold index, impulses)` for every manifold, batch by batch (see
    /// [`LaneResult::impact`] for `jitter`).
    pub(crate) fn for_each_result(&self, jitter: Jitter, mut f: impl FnMut(u32, &LaneResult)) {
        self.four
            .iter()
            .for_each(|b| b.for_each_result(jitter, &mut f));
        self.one
            .iter()
            .for_each(|b| b.for_each_result(jitter, &mut f));
        self.four_linear
            .iter()
            .for_each(|b| b.for_each_result(jitter, &mut f));
        self.one_linear
            .iter()
            .for_each(|b| b.for_each_result(jitter, &mut f));
    }
}

#[cfg(test)]
mod tests {
    use glam::Vec3A;

    use super::*;
    use crate::solver::contact_constraint::{
        ConstraintPoint, ContactConstraint, FrictionPart, NormalBlock,
    };
    use crate::solver::Softness;

    fn manifold(body_a: u32, body_b: u32, writes: u8, count: u8) -> ManifoldRef {
        ManifoldRef {
            pair: 0,
            manifold: 0,
            body_a,
            body_b,
            writes,
            count,
            // Bodies with an index divisible by 5 cannot rotate.
            angular: !body_a.is_multiple_of(5) || !body_b.is_multiple_of(5),
            rests: 0,
        }
    }

    fn prepared(r: &ManifoldRef) -> PreparedManifold {
        PreparedManifold {
            constraint: ContactConstraint {
                body_a: r.body_a,
                body_b: r.body_b,
                writes: r.writes,
                angular: r.angular,
                normal: Vec3A::Y,
                tangent: [Vec3A::X, Vec3A::Z],
                restitution: 0.0,
                elastic: false,
                column: false,
                column_friction: false,
                bounce_accel: 0.0,
                pressing: [Vec3A::ZERO; 2],
                load_level_share: 0.0,
                mass_scale: [1.0; 2],
                softness: Softness::RIGID,
                touching: 0.0,
                count: r.count,
                friction: FrictionPart::default(),
                block: NormalBlock::default(),
            },
            points: [ConstraintPoint::default(); 4],
        }
    }

    /// Every manifold lands in exactly one lane of one batch of its layout, prepared once,
    /// and no batch has a written body twice.
    #[test]
    fn every_manifold_once_and_no_written_body_twice_in_a_batch() {
        let bodies = 80u32;
        let mut constraints = Vec::new();
        // A chain (each body touches the next), all on the static ground (index 0, never
        // written), and a hub, body 1, touching every other body (79 contacts).
        for b in 2..bodies {
            constraints.push(manifold(b - 1, b, 3, 4));
            constraints.push(manifold(0, b, 2, if b % 10 == 0 { 4 } else { 1 }));
            constraints.push(manifold(1, b, 3, if b % 2 == 0 { 1 } else { 3 }));
        }
        let states = vec![BodyState::STATIC; bodies as usize];
        let mut batches = ContactBatches::default();
        let mut prepared_count = 0;
        batches.build(&constraints, &states, |r, out| {
            prepared_count += 1;
            *out = prepared(r);
        });
        assert_eq!(prepared_count, constraints.len());

        let mut seen = vec![0u32; constraints.len()];
        let mut check = |lanes: &[u32; LANES], four: bool, angular: bool| {
            let mut written = Vec::new();
            for &ci in lanes.iter().filter(|&&ci| ci != u32::MAX) {
                seen[ci as usize] += 1;
                let c = &constraints[ci as usize];
                assert_eq!(c.count > 1, four, "constraint {ci} in the wrong layout");
                assert_eq!(c.angular, angular, "constraint {ci} in the wrong kind");
                for (bit, body) in [(1u8, c.body_a), (2, c.body_b)] {
                    if c.writes & bit != 0 {
                        assert!(!written.contains(&body), "body {body} twice in {lanes:?}");
                        written.push(body);
                    }
                }
            }
        };
        batches
            .four
            .iter()
            .for_each(|b| check(&b.constraint, true, true));
        batches
            .one
            .iter()
            .for_each(|b| check(&b.constraint, false, true));
        batches
            .four_linear
            .iter()
            .for_each(|b| check(&b.constraint, true, false));
        batches
            .one_linear
            .iter()
            .for_each(|b| check(&b.constraint, false, false));
        assert!(seen.iter().all(|&n| n == 1), "{seen:?}");
        // Every kind was exercised.
        assert!(!batches.four_linear.is_empty() && !batches.one_linear.is_empty());
    }
}
