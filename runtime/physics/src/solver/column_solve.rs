//! [`ColumnSolve`]: a coarse correction of the step's columns, solved exactly, between the
//! Gauss–Seidel passes over their faces.
//!
//! A column of small bodies needs stiff faces (a 1 mm cube's depth budget is tens of
//! micrometres), and Gauss–Seidel carries a load down a chain of stiff faces one face per
//! pass: the errors that converge slowest are the smooth ones, every face of the column
//! pressed a little too far or too little, or every face tilted the same way, which a sweep
//! moves by a fraction of the ratio of a face's stiffness to the chain's. This is the
//! two-level (aggregation multigrid) remedy: each face's point impulses are aggregated into
//! three unknowns — the face's force (an impulse shared equally among its points, the shared
//! step of `FaceContact::solve_shared` for one face alone) and its two moments (impulses
//! growing linearly across the face) — and the faces of one column, linked through the bodies
//! they both move, are solved together, exactly, from the residuals of their rows. The coarse
//! system is the Galerkin product `Pᵀ(J M⁻¹ Jᵀ + C)P`: `P` the three weightings of each face's
//! points, `J` their normal rows, `M⁻¹` the bodies' inverse masses and inertias, `C` the
//! compliance of the soft rows (with the leak of a levelled face). It is small (a column of
//! ten cubes is thirty unknowns), symmetric positive definite, and solved by Cholesky; its
//! faces ordered so that linked ones sit together (Cuthill–McKee), a column's system is
//! banded and its factor keeps to the band (an envelope, or skyline, factor).
//!
//! A face under or on a pinched body (one a body three times heavier rests on, as in a heavy
//! body's column on a light one) brings its two friction rows too, the impulses at its
//! centre that `ContactBatch::solve_friction` solves: sticking, as equalities (the
//! tangential velocity at the centre held at zero), then held within the friction cone of
//! the new normal impulses. A light body between two faces with friction is held sideways
//! and in tilt by both at once, far more stiffly than its own inertia, and the passes alone
//! let its tilt whirl (a 1 cm cube on its true mass under a 10 cm one was squeezed out at
//! every preset; solved here, it stands within 2 % at each). What the unknowns cannot
//! express — the rest of a face's spread, the twist — is left to the Gauss–Seidel passes
//! around each correction.

use std::collections::HashMap;

use glam::Vec3A;

use super::body_state::BodyState;
use super::contact_batch::{FaceBatch, LinearFaceBatch, Pass};
use super::lanes::{F, LANES};

/// Most faces one coarse system holds; a larger group of linked column faces is solved in
/// consecutive runs of this many (each still exact for its own faces). Bounded `[1, ∞)`: the
/// factorisation of a group linked every face to every other costs the cube of it (a
/// column's, banded, only its length), and no scene here has a group of more than 40.
pub const MAX_COLUMN_GROUP: usize = 64;

/// Normal aggregates per face: its force and its two moments.
const DOFS: usize = 3;

/// Unknowns per face at most: its normal aggregates and, where it has friction, its two
/// friction impulses at the face's centre (the rows `ContactBatch::solve_friction` solves).
const UNKNOWNS: usize = DOFS + 2;

/// A face's moment is left out of the coarse system where the points' spread along it is
/// below this fraction of their largest lever (a two-point edge contact has one moment).
const MIN_SPREAD: f32 = 1e-3;

/// A face's moment is left out of the coarse system where it moves the bodies less than this
/// fraction of what its force does (per unit of orthonormal weight): a body whose rotation is
/// locked gives a moment nothing to turn.
const MIN_MOMENT_MOBILITY: f32 = 1e-4;

/// How much the force aggregate (index 0) of a face moves its bodies: `J₀ M⁻¹ J₀ᵀ`.
fn self_force_mobility(
    jacobian: &[[[Vec3A; 2]; 2]; UNKNOWNS],
    through_mass: &[[[Vec3A; 2]; 2]; UNKNOWNS],
    writes: [bool; 2],
) -> f32 {
    (0..2)
        .filter(|&s| writes[s])
        .map(|s| {
            jacobian[0][s][0].dot(through_mass[0][s][0])
                + jacobian[0][s][1].dot(through_mass[0][s][1])
        })
        .sum()
}

/// A column face's normal rows as [`ContactBatch::column_rows`](super::contact_batch::ContactBatch::column_rows)
/// reads them in one pass, per lane and point: the residual of the row's fixed point (normal
/// velocity, bias and the soft row's leak through its compliance, `vn + b + c·leak`), the
/// compliance, and how much of a levelled face's leak is its mean impulse.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ColumnRows {
    pub residual: [F; 4],
    pub compliance: [F; 4],
    pub level_share: F,
    /// The points' accumulated normal impulses.
    pub impulse: [F; 4],
    /// The friction rows' relative tangential velocities at the face's centre: their
    /// residual (they hold it at zero while sticking).
    pub tangent_velocity: [F; 2],
}

/// A face's friction rows at its centre, per side (A, B) and tangent: `r × t`, and the same
/// through the side's world inverse inertia.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FrictionLevers {
    pub rt: [[Vec3A; 2]; 2],
    pub irt: [[Vec3A; 2]; 2],
}

/// One column face as the coarse correction sees it: its aggregate rows.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ColumnFace {
    /// Solver indices of bodies A and B.
    bodies: [u32; 2],
    /// Whether the solver moves A (resp. B): it is dynamic.
    writes: [bool; 2],
    /// How many of the three aggregates the face has (1 between bodies that do not rotate,
    /// or where its points lie on one spot).
    dofs: usize,
    /// Whether the face's two friction rows are unknowns too (after its `dofs`).
    friction: bool,
    /// Per aggregate, each point's share of its impulse (orthonormal over the points).
    weights: [[f32; 4]; DOFS],
    /// Per unknown and side (A, B): its row's linear and angular parts.
    jacobian: [[[Vec3A; 2]; 2]; UNKNOWNS],
    /// The same through the side's inverse mass and world inverse inertia.
    through_mass: [[[Vec3A; 2]; 2]; UNKNOWNS],
}

impl ColumnFace {
    /// The face between `bodies` with normal `n` and tangents `t`, from its points' levers
    /// (`r × n` per side, and through the inverse inertia; zero between bodies that do not
    /// rotate) and its sides' inverse masses (per axis); with `friction`, its friction rows'
    /// levers at the face's centre (`r × t` per side and tangent, and through the inverse
    /// inertia).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        bodies: [u32; 2],
        writes: [bool; 2],
        n: Vec3A,
        t: [Vec3A; 2],
        inv_mass: [Vec3A; 2],
        active: [bool; 4],
        rn: [[Vec3A; 4]; 2],
        irn: [[Vec3A; 4]; 2],
        friction: Option<FrictionLevers>,
    ) -> Self {
        let count = active.iter().filter(|&&a| a).count().max(1) as f32;
        let mask = |k: usize| if active[k] { 1.0 } else { 0.0 };
        // Force: equal shares. Moments: each point's offset from the face's centre along the
        // tangents (`(r − r̄) × n` lies in the face), made orthogonal to the others.
        let mut weights = [[0.0f32; 4]; DOFS];
        weights[0] = std::array::from_fn(|k| mask(k) / count.sqrt());
        let centre = (0..4).map(|k| rn[0][k] * mask(k)).sum::<Vec3A>() / count;
        let offsets: [Vec3A; 4] = std::array::from_fn(|k| (rn[0][k] - centre) * mask(k));
        let reach = offsets.iter().map(|o| o.length()).fold(0.0f32, f32::max);
        let mut dofs = 1;
        for tangent in t {
            let mut w: [f32; 4] = std::array::from_fn(|k| offsets[k].dot(tangent));
            for prev in &weights[..dofs] {
                let d: f32 = (0..4).map(|k| w[k] * prev[k]).sum();
                (0..4).for_each(|k| w[k] -= d * prev[k]);
            }
            let norm = w.iter().map(|x| x * x).sum::<f32>().sqrt();
            if norm > MIN_SPREAD * reach && norm > 0.0 {
                weights[dofs] = w.map(|x| x / norm);
                dofs += 1;
            }
        }
        let sign = [-1.0, 1.0];
        let mut jacobian = [[[Vec3A::ZERO; 2]; 2]; UNKNOWNS];
        let mut through_mass = [[[Vec3A::ZERO; 2]; 2]; UNKNOWNS];
        let mut kept = 0;
        for d in 0..dofs {
            let w = weights[d];
            let total: f32 = w.iter().sum();
            let (mut j, mut m) = ([[Vec3A::ZERO; 2]; 2], [[Vec3A::ZERO; 2]; 2]);
            let mut moves = 0.0;
            for s in 0..2 {
                let ang: Vec3A = (0..4).map(|k| rn[s][k] * w[k]).sum();
                let iang: Vec3A = (0..4).map(|k| irn[s][k] * w[k]).sum();
                j[s] = [n * total * sign[s], ang * sign[s]];
                m[s] = [inv_mass[s] * n * total * sign[s], iang * sign[s]];
                if writes[s] {
                    moves += j[s][0].dot(m[s][0]) + j[s][1].dot(m[s][1]);
                }
            }
            // A moment that turns neither body (rotation locked) is left to the passes.
            let floor = MIN_MOMENT_MOBILITY * self_force_mobility(&jacobian, &through_mass, writes);
            if d > 0 && moves.partial_cmp(&floor) != Some(std::cmp::Ordering::Greater) {
                continue;
            }
            weights[kept] = w;
            jacobian[kept] = j;
            through_mass[kept] = m;
            kept += 1;
        }
        let dofs = kept;
        if let Some(FrictionLevers { rt, irt }) = friction {
            for (k, &tangent) in t.iter().enumerate() {
                for s in 0..2 {
                    jacobian[dofs + k][s] = [tangent * sign[s], rt[s][k] * sign[s]];
                    through_mass[dofs + k][s] =
                        [inv_mass[s] * tangent * sign[s], irt[s][k] * sign[s]];
                }
            }
        }
        Self {
            bodies,
            writes,
            dofs,
            friction: friction.is_some(),
            weights,
            jacobian,
            through_mass,
        }
    }

    /// Its unknowns: its normal aggregates, then its friction rows where it has them.
    fn unknowns(&self) -> usize {
        self.dofs + if self.friction { 2 } else { 0 }
    }

    /// `J_d M⁻¹ J_eᵀ` of aggregate `d` of `self` and `e` of `other`: how the first's velocity
    /// moves per unit of the second's impulse, through the bodies they share (and move).
    fn coupling(&self, d: usize, other: &Self, e: usize) -> f32 {
        let mut k = 0.0;
        for s in 0..2 {
            for t in 0..2 {
                if self.writes[s] && other.writes[t] && self.bodies[s] == other.bodies[t] {
                    let [lin, ang] = self.jacobian[d][s];
                    let [m_lin, m_ang] = other.through_mass[e][t];
                    k += lin.dot(m_lin) + ang.dot(m_ang);
                }
            }
        }
        k
    }
}

/// Where a column face sits among the step's batches.
#[derive(Clone, Copy, Debug)]
struct Located {
    /// Index into [`ColumnSolve::batches`].
    batch: u32,
    lane: u8,
    face: ColumnFace,
}

/// A batch holding column faces: a linear one (`four_linear`) or not (`four`), and its index.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct BatchRef {
    linear: bool,
    index: u32,
}

/// Faces solved together: `faces[start..start + len]`, with `size` unknowns (their
/// aggregates), whose coupling matrix starts at `coupling[matrix]` (`size × size`,
/// row-major), as does its factor in `factors`, whose rows' first columns inside the
/// envelope start at `envelope[rows]` (`size`), and whose rows' compliances and level
/// shares that factor was made with start at `factored_with[key]` (`len × 5`).
#[derive(Clone, Copy, Debug)]
struct Group {
    start: usize,
    len: usize,
    size: usize,
    matrix: usize,
    rows: usize,
    key: usize,
    /// `factors` holds this group's factor, made with `factored_with`.
    factored: bool,
}

/// Per face, what its part of a group's coarse system depends on beyond the coupling: its
/// four points' compliances and its level share.
const KEY_PER_FACE: usize = 5;

/// The step's column faces, grouped by column, with their coupling (see the module).
#[derive(Debug, Default)]
pub(crate) struct ColumnSolve {
    faces: Vec<Located>,
    batches: Vec<BatchRef>,
    groups: Vec<Group>,
    coupling: Vec<f32>,
    /// Per group, the Cholesky factor of its coarse system (the coupling and its rows'
    /// leak), kept while the rows' compliances and shares stay those it was made with: they
    /// change within a step only where a point parts or touches, and factored again at each
    /// of its 16 passes a substep (`solve::COLUMN_PASSES`) the coarse correction of a
    /// 20-box stack at 30 Hz × 2 cost 0.8 ms a step.
    factors: Vec<f32>,
    /// Per group and row of its coarse system, the first column inside its envelope: every
    /// entry left of it is zero, in the coupling and in its factor (see [`cholesky_factor`]).
    envelope: Vec<u32>,
    factored_with: Vec<f32>,
    /// Scratch of [`ColumnSolve::correct`]: per batch, its rows and its points' impulses.
    rows: Vec<ColumnRows>,
    impulse: Vec<[F; 4]>,
    tangent: Vec<[F; 2]>,
    /// Scratch: one group's rows' compliances and shares, and its right-hand side.
    key: Vec<f32>,
    rhs: Vec<f32>,
}

impl ColumnSolve {
    /// Whether the step has column faces.
    pub(crate) fn is_empty(&self) -> bool {
        self.faces.is_empty()
    }

    /// Collects the column faces of the step's face batches and groups them by the dynamic
    /// bodies they share.
    pub(crate) fn build(&mut self, four: &[FaceBatch], four_linear: &[LinearFaceBatch]) {
        self.faces.clear();
        self.batches.clear();
        self.groups.clear();
        self.coupling.clear();
        self.envelope.clear();
        self.factored_with.clear();
        let mut found = Vec::new();
        let mut collect =
            |linear: bool, index: usize, face: &dyn Fn(usize) -> Option<ColumnFace>| {
                let batch = BatchRef {
                    linear,
                    index: index as u32,
                };
                found.extend((0..LANES).filter_map(|l| face(l).map(|f| (batch, l as u8, f))));
            };
        for (i, b) in four.iter().enumerate().filter(|(_, b)| b.has_column()) {
            collect(false, i, &|l| b.column_face(l));
        }
        for (i, b) in four_linear
            .iter()
            .enumerate()
            .filter(|(_, b)| b.has_column())
        {
            collect(true, i, &|l| b.column_face(l));
        }
        if found.is_empty() {
            return;
        }
        // Union–find over the faces, linked through each dynamic body they move.
        let mut parent: Vec<usize> = (0..found.len()).collect();
        fn root(parent: &mut [usize], mut i: usize) -> usize {
            while parent[i] != i {
                parent[i] = parent[parent[i]];
                i = parent[i];
            }
            i
        }
        let mut first_on: HashMap<u32, usize> = HashMap::new();
        for (i, (_, _, face)) in found.iter().enumerate() {
            for s in 0..2 {
                if !face.writes[s] {
                    continue;
                }
                let j = *first_on.entry(face.bodies[s]).or_insert(i);
                let (ri, rj) = (root(&mut parent, i), root(&mut parent, j));
                parent[ri.max(rj)] = ri.min(rj);
            }
        }
        let mut order: Vec<(usize, usize)> = (0..found.len())
            .map(|i| (root(&mut parent, i), i))
            .collect();
        order.sort_unstable();
        for group in order.chunk_by_mut(|a, b| a.0 == b.0) {
            linked_order(group, &found);
        }
        for (_, i) in &order {
            let (batch, lane, face) = found[*i];
            let batch = match self.batches.iter().position(|&b| b == batch) {
                Some(k) => k,
                None => {
                    self.batches.push(batch);
                    self.batches.len() - 1
                }
            };
            self.faces.push(Located {
                batch: batch as u32,
                lane,
                face,
            });
        }
        let mut start = 0;
        for group in order.chunk_by(|a, b| a.0 == b.0) {
            let end = start + group.len();
            for run in (start..end).step_by(MAX_COLUMN_GROUP) {
                let len = (end - run).min(MAX_COLUMN_GROUP);
                let faces = &self.faces[run..run + len];
                let size = faces.iter().map(|f| f.face.unknowns()).sum();
                let matrix = self.coupling.len();
                for f in faces {
                    for d in 0..f.face.unknowns() {
                        for g in faces {
                            for e in 0..g.face.unknowns() {
                                self.coupling.push(f.face.coupling(d, &g.face, e));
                            }
                        }
                    }
                }
                let rows = self.envelope.len();
                let mut at = 0;
                for f in faces {
                    for d in 0..f.face.unknowns() {
                        // The face's own block is inside: its rows' leak fills it.
                        let row = &self.coupling[matrix + (at + d) * size..][..at + d];
                        let first = row.iter().position(|&k| k != 0.0).unwrap_or(at).min(at);
                        self.envelope.push(first as u32);
                    }
                    at += f.face.unknowns();
                }
                self.groups.push(Group {
                    start: run,
                    len,
                    size,
                    matrix,
                    rows,
                    key: self.factored_with.len(),
                    factored: false,
                });
                self.factored_with
                    .resize(self.factored_with.len() + len * KEY_PER_FACE, f32::NAN);
            }
            start = end;
        }
        self.factors.resize(self.coupling.len(), 0.0);
    }

    /// One coarse correction: every column face's residuals from the bodies' current
    /// velocities and positions, the aggregate impulses that zero their aggregates all at
    /// once, spread over the faces' points, applied; a group whose answer would pull a point
    /// is left to the passes.
    pub(crate) fn correct(
        &mut self,
        four: &mut [FaceBatch],
        four_linear: &mut [LinearFaceBatch],
        states: &mut [BodyState],
        pass: Pass,
    ) {
        self.rows.clear();
        for b in &self.batches {
            let i = b.index as usize;
            self.rows.push(if b.linear {
                four_linear[i].column_rows(states, pass)
            } else {
                four[i].column_rows(states, pass)
            });
        }
        self.impulse.clear();
        self.impulse.resize(self.batches.len(), [F::ZERO; 4]);
        self.tangent.clear();
        self.tangent.resize(self.batches.len(), [F::ZERO; 2]);
        for gi in 0..self.groups.len() {
            let g = self.groups[gi];
            let n = g.size;
            let faces = &self.faces[g.start..g.start + g.len];
            self.rhs.clear();
            self.key.clear();
            for f in faces {
                let rows = &self.rows[f.batch as usize];
                let lane = usize::from(f.lane);
                let residual = rows.residual.map(|r| r.to_array()[lane]);
                let face = &f.face;
                for w in &face.weights[..face.dofs] {
                    self.rhs
                        .push(-(0..4).map(|k| w[k] * residual[k]).sum::<f32>());
                }
                if face.friction {
                    for v in rows.tangent_velocity {
                        self.rhs.push(-v.to_array()[lane]);
                    }
                }
                self.key.extend(rows.compliance.map(|c| c.to_array()[lane]));
                self.key.push(rows.level_share.to_array()[lane]);
            }
            let key = g.key..g.key + g.len * KEY_PER_FACE;
            // Compared bit for bit: a NaN compliance never matches, and is factored (and
            // refused) again.
            let same = g.factored
                && self.factored_with[key.clone()]
                    .iter()
                    .zip(&self.key)
                    .all(|(a, b)| a.to_bits() == b.to_bits());
            if !same {
                let factor = &mut self.factors[g.matrix..g.matrix + n * n];
                factor.copy_from_slice(&self.coupling[g.matrix..g.matrix + n * n]);
                add_leak(factor, n, faces, &self.key);
                let ok = cholesky_factor(factor, n, &self.envelope[g.rows..g.rows + n]);
                self.factored_with[key].copy_from_slice(&self.key);
                self.groups[gi].factored = ok;
                if !ok {
                    continue;
                }
            }
            // Non-finite residuals (a body gone to NaN) leave the group to the passes.
            if !self.rhs.iter().all(|r| r.is_finite()) {
                continue;
            }
            cholesky_substitute(
                &self.factors[g.matrix..g.matrix + n * n],
                &self.envelope[g.rows..g.rows + n],
                &mut self.rhs,
            );
            // The coarse system takes every point for pressing (an equality). Where its
            // answer would pull a point (a column coming apart, a pile collapsing), the group
            // is left to the passes: clamped point by point, a face's moment became a push,
            // 16 times a substep, and the 100-row pyramid collapsing at 30 Hz × 2 threw a
            // brick 10 km in 500 steps (rapier's 101 m; 101 m now). No column that stands
            // is changed (`tests/stacking.rs`, every figure the same).
            if self.would_pull(faces) {
                continue;
            }
            let mut at = 0;
            for f in faces {
                let face = &f.face;
                let lanes = &mut self.impulse[f.batch as usize];
                let lane = usize::from(f.lane);
                for (k, point) in lanes.iter_mut().enumerate() {
                    let mut a = point.to_array();
                    a[lane] = (0..face.dofs)
                        .map(|d| self.rhs[at + d] * face.weights[d][k])
                        .sum();
                    *point = F::from(a);
                }
                if face.friction {
                    let tangent = &mut self.tangent[f.batch as usize];
                    for (k, t) in tangent.iter_mut().enumerate() {
                        let mut a = t.to_array();
                        a[lane] = self.rhs[at + face.dofs + k];
                        *t = F::from(a);
                    }
                }
                at += face.unknowns();
            }
        }
        for ((b, &impulse), &tangent) in self.batches.iter().zip(&self.impulse).zip(&self.tangent) {
            let i = b.index as usize;
            if b.linear {
                four_linear[i].add_column_impulses(states, impulse, tangent);
            } else {
                four[i].add_column_impulses(states, impulse, tangent);
            }
        }
    }

    /// Whether the group `faces`' solved aggregates (`rhs`) would take some point's normal
    /// impulse below zero.
    fn would_pull(&self, faces: &[Located]) -> bool {
        let mut at = 0;
        for f in faces {
            let face = &f.face;
            let lane = usize::from(f.lane);
            let now = self.rows[f.batch as usize].impulse;
            for (k, now) in now.iter().enumerate() {
                if face.weights[0][k] == 0.0 {
                    continue;
                }
                let delta: f32 = (0..face.dofs)
                    .map(|d| self.rhs[at + d] * face.weights[d][k])
                    .sum();
                if now.to_array()[lane] + delta < 0.0 {
                    return true;
                }
            }
            at += face.unknowns();
        }
        false
    }
}

/// Adds to a group's coupling (`a`, `n × n`) its soft rows' leak: per face, how each
/// aggregate moves the rows' leak through each other's weights, made symmetric, from the
/// points' compliances and the face's level share (`key`, [`KEY_PER_FACE`] per face).
fn add_leak(a: &mut [f32], n: usize, faces: &[Located], key: &[f32]) {
    let mut at = 0;
    for (f, key) in faces.iter().zip(key.chunks_exact(KEY_PER_FACE)) {
        let face = &f.face;
        let (compliance, share) = (&key[..4], key[4]);
        let points = face.weights[0].iter().filter(|&&w| w != 0.0).count().max(1);
        let leak = |d: usize, e: usize| {
            let (wd, we) = (face.weights[d], face.weights[e]);
            let mean = we.iter().sum::<f32>() / points as f32;
            (0..4)
                .map(|k| compliance[k] * wd[k] * (we[k] * (1.0 - share) + share * mean))
                .sum::<f32>()
        };
        for d in 0..face.dofs {
            for e in 0..face.dofs {
                a[(at + d) * n + at + e] += 0.5 * (leak(d, e) + leak(e, d));
            }
        }
        at += face.unknowns();
    }
}

/// Orders the faces of one group (`(root, index into found)`) so that faces linked through
/// a body sit close together (Cuthill–McKee: breadth first from a face with the fewest
/// links, each face's links visited fewest first). A column comes out bottom to top or top
/// to bottom, and its coarse system banded: a face couples only to the faces next to it.
fn linked_order(group: &mut [(usize, usize)], found: &[(BatchRef, u8, ColumnFace)]) {
    if group.len() <= 2 {
        return;
    }
    let mut on_body: HashMap<u32, Vec<usize>> = HashMap::new();
    for (at, &(_, i)) in group.iter().enumerate() {
        let face = &found[i].2;
        for s in (0..2).filter(|&s| face.writes[s]) {
            on_body.entry(face.bodies[s]).or_default().push(at);
        }
    }
    let links = |at: usize| {
        let face = &found[group[at].1].2;
        let mut linked: Vec<usize> = (0..2)
            .filter(|&s| face.writes[s])
            .flat_map(|s| on_body[&face.bodies[s]].iter().copied())
            .filter(|&other| other != at)
            .collect();
        linked.sort_unstable();
        linked.dedup();
        linked
    };
    let degree: Vec<usize> = (0..group.len()).map(|at| links(at).len()).collect();
    let mut placed = vec![false; group.len()];
    let mut sequence = Vec::with_capacity(group.len());
    while sequence.len() < group.len() {
        let Some(seed) = (0..group.len())
            .filter(|&at| !placed[at])
            .min_by_key(|&at| degree[at])
        else {
            break;
        };
        placed[seed] = true;
        let mut next = sequence.len();
        sequence.push(seed);
        while next < sequence.len() {
            let mut linked = links(sequence[next]);
            linked.retain(|&at| !placed[at]);
            linked.sort_by_key(|&at| degree[at]);
            for at in linked {
                placed[at] = true;
                sequence.push(at);
            }
            next += 1;
        }
    }
    let ordered: Vec<(usize, usize)> = sequence.iter().map(|&at| group[at]).collect();
    group.copy_from_slice(&ordered);
}

/// Solves `A x = b` in place for a symmetric positive definite `A` (`n × n`, row-major; its
/// lower triangle is overwritten by the Cholesky factor, `b` by `x`) whose row `i` is zero
/// left of column `first[i]`. Returns `false`, and leaves `b` unusable, where a pivot is not
/// positive and finite.
#[cfg(test)]
fn cholesky_solve(a: &mut [f32], first: &[u32], b: &mut [f32]) -> bool {
    let ok = cholesky_factor(a, b.len(), first);
    if ok {
        cholesky_substitute(a, first, b);
    }
    ok
}

/// Overwrites the lower triangle of a symmetric positive definite `a` (`n × n`, row-major)
/// with its Cholesky factor `L`. Row `i` of `a` is zero left of column `first[i]` (its
/// envelope), and so is row `i` of `L`: only the envelope is computed, in `n·w²` for a band
/// `w` wide. Returns `false` where a pivot is not positive and finite.
fn cholesky_factor(a: &mut [f32], n: usize, first: &[u32]) -> bool {
    let first = |i: usize| first[i] as usize;
    for j in 0..n {
        let row_j = j * n;
        let mut d = a[row_j + j];
        for k in first(j)..j {
            d -= a[row_j + k] * a[row_j + k];
        }
        if !(d > 0.0 && d.is_finite()) {
            return false;
        }
        let d = d.sqrt();
        a[row_j + j] = d;
        for i in (j + 1..n).filter(|&i| first(i) <= j) {
            let row_i = i * n;
            let mut s = a[row_i + j];
            for k in first(i).max(first(j))..j {
                s -= a[row_i + k] * a[row_j + k];
            }
            a[row_i + j] = s / d;
        }
    }
    true
}

/// Solves `L Lᵀ x = b` in place (`b` becomes `x`) for the factor [`cholesky_factor`] left in
/// the lower triangle of `a` with the envelope `first`.
fn cholesky_substitute(a: &[f32], first: &[u32], b: &mut [f32]) {
    let n = b.len();
    // L y = b, row by row; then Lᵀ x = y, column by column of Lᵀ (row by row of L).
    for i in 0..n {
        let row = &a[i * n..];
        let mut s = b[i];
        for k in first[i] as usize..i {
            s -= row[k] * b[k];
        }
        b[i] = s / row[i];
    }
    for i in (0..n).rev() {
        let row = &a[i * n..];
        b[i] /= row[i];
        let x = b[i];
        for k in first[i] as usize..i {
            b[k] -= row[k] * x;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cholesky_solves_a_symmetric_positive_definite_system() {
        // A tridiagonal chain (a column of three faces on the ground) and its solution, dense
        // and in its envelope.
        let a = [2.0, -1.0, 0.0, -1.0, 2.0, -1.0, 0.0, -1.0, 2.0f32];
        let x = [1.0, -2.0, 0.5f32];
        for first in [[0, 0, 0], [0, 0, 1]] {
            let mut b: Vec<f32> = (0..3)
                .map(|i| (0..3).map(|j| a[i * 3 + j] * x[j]).sum())
                .collect();
            let mut f = a.to_vec();
            assert!(cholesky_solve(&mut f, &first, &mut b));
            for (got, want) in b.iter().zip(x) {
                assert!((got - want).abs() < 1e-5, "{got} vs {want}");
            }
        }
        // Not positive definite: refused.
        let mut f = vec![1.0, 2.0, 2.0, 1.0];
        assert!(!cholesky_solve(&mut f, &[0, 0], &mut [1.0, 1.0]));
    }

    #[test]
    fn an_envelope_factor_solves_a_banded_system_with_a_ragged_edge() {
        // Rows whose envelopes start at 0, 0, 1, 1, 3, 2 (a face of two unknowns beside
        // faces of one): the envelope solve matches the dense one.
        let n = 6;
        let first = [0u32, 0, 1, 1, 3, 2];
        let mut a = vec![0.0f32; n * n];
        for i in 0..n {
            for j in first[i] as usize..i {
                let v = -0.3 - 0.05 * (i + j) as f32;
                a[i * n + j] = v;
                a[j * n + i] = v;
            }
            a[i * n + i] = 3.0 + i as f32 * 0.1;
        }
        let b: Vec<f32> = (0..n).map(|i| (i as f32 - 2.5) * 0.7).collect();
        let (mut dense, mut enveloped) = (a.clone(), a);
        let (mut x_dense, mut x_env) = (b.clone(), b);
        assert!(cholesky_solve(&mut dense, &[0; 6], &mut x_dense));
        assert!(cholesky_solve(&mut enveloped, &first, &mut x_env));
        for (e, d) in x_env.iter().zip(&x_dense) {
            assert!((e - d).abs() < 1e-5, "{e} vs {d}");
        }
    }
}
