//! How many faces each solver body rests on: what tells a column (each body on one face)
//! from a pyramid (bricks on two), and the mass a body carries down a column. Counted only
//! when some face first asks, once a step.

use glam::Vec3;

use super::heavy_on_light::upper_lower;
use crate::narrowphase::contact_pair::ContactPair;
use crate::solver::body_state::BodyState;
use crate::solver::contact_constraint::{touching_distance, ManifoldRef};

/// A face supports the body above it when its normal is within this cosine of the vertical
/// (45°): a column's faces, not a wall's.
pub const SUPPORT_MIN_COS: f32 = std::f32::consts::FRAC_1_SQRT_2;

/// Per solver body, the touching faces (two points or more, within [`SUPPORT_MIN_COS`] of
/// gravity) it is the upper body of; a speculative face two cubes up does not count.
///
/// Asked by a face the depth budget stiffens past `COLUMN_STIFFNESS` (or one at the base
/// rate under a column, `Self::carries_column`), and by every face with friction whose
/// chain may need levelling (`ChainFace::level_share`): counted every step wherever a body rests
/// on one face with friction (the 20-row pyramid's bottom row on the ground does, about 1 %
/// of its step).
#[derive(Debug, Default)]
pub(crate) struct ColumnSupports {
    counts: Vec<u8>,
    /// Per solver body, the lower body of the last support face counted for it (its only
    /// one where `counts` is 1).
    below: Vec<u32>,
    counted: bool,
    /// Per solver body, its mass and the masses of the bodies resting on it through one face
    /// each, up the column (see [`Self::column_mass`]); empty until first asked.
    column_masses: Vec<f32>,
    /// Per solver body, how many bodies its column holds: it, those resting on it through
    /// one face each up the column, and those it rests on so down to the base (see
    /// [`Self::column_length`]); empty until first asked.
    column_lengths: Vec<u16>,
    /// Per body (arena index), whether a column face rested on it at the end of the last
    /// step (see [`Self::carries_column`]).
    columns_on: Vec<bool>,
}

/// Longest column [`ColumnSupports::column_mass`] walks down from a body: the bound of its
/// cost, far past any column one face can carry within its budget.
pub const MAX_COLUMN_WALK: usize = 256;

impl ColumnSupports {
    /// Forgets last step's counts (they are counted again when first asked).
    pub fn reset(&mut self) {
        self.counted = false;
        self.column_masses.clear();
        self.column_lengths.clear();
    }

    /// The mass solver body `body` holds up: its own (`mass_of`) and that of every body
    /// resting on it through one face each, and on those, up the column (a pyramid's brick
    /// rests on two and adds to neither). The load a new face carries from its first step,
    /// before its warm-started impulse has grown to it.
    pub fn column_mass(
        &mut self,
        body: u32,
        manifolds: &[ManifoldRef],
        pairs: &[ContactPair],
        gravity: Vec3,
        states: &[BodyState],
        mass_of: impl Fn(&BodyState) -> f32,
    ) -> f32 {
        if !self.counted {
            self.count(manifolds, pairs, gravity);
        }
        if self.column_masses.is_empty() {
            self.column_masses.extend(states.iter().map(&mass_of));
            for top in 0..self.counts.len().min(states.len()) {
                if self.counts[top] != 1 {
                    continue;
                }
                let mass = mass_of(&states[top]);
                let (counts, below) = (&self.counts, &self.below);
                for down in Self::down_from(counts, below, top, states.len()) {
                    self.column_masses[down] += mass;
                }
            }
        }
        self.column_masses
            .get(body as usize)
            .copied()
            .unwrap_or(0.0)
    }

    /// How many dynamic bodies the column of solver body `body` holds: it, every body
    /// resting on it through one face each and on those up the column, and every body it
    /// rests on so down to the column's base (one a pyramid's brick rests on two of is
    /// its base). 1 for a body in no column; 0 for the static body.
    pub fn column_length(
        &mut self,
        body: u32,
        manifolds: &[ManifoldRef],
        pairs: &[ContactPair],
        gravity: Vec3,
        bodies: usize,
    ) -> u16 {
        if body == 0 {
            return 0;
        }
        if !self.counted {
            self.count(manifolds, pairs, gravity);
        }
        if self.column_lengths.is_empty() {
            // Each body walks down its column: it counts in the length of every body under
            // it, and those count in its own.
            self.column_lengths.resize(bodies, 1);
            let (counts, below) = (&self.counts, &self.below);
            for top in 0..counts.len().min(bodies) {
                let mut under = 0u16;
                for down in Self::down_from(counts, below, top, bodies) {
                    self.column_lengths[down] = self.column_lengths[down].saturating_add(1);
                    under = under.saturating_add(1);
                }
                self.column_lengths[top] = self.column_lengths[top].saturating_add(under);
            }
        }
        self.column_lengths.get(body as usize).copied().unwrap_or(1)
    }

    /// The dynamic bodies under solver body `body` down its column, as
    /// [`Self::down_from`] walks them.
    pub fn column_below(
        &mut self,
        body: u32,
        manifolds: &[ManifoldRef],
        pairs: &[ContactPair],
        gravity: Vec3,
        bodies: usize,
    ) -> impl Iterator<Item = usize> + '_ {
        if !self.counted {
            self.count(manifolds, pairs, gravity);
        }
        Self::down_from(&self.counts, &self.below, body as usize, bodies)
    }

    /// The dynamic bodies under solver body `top` down its column: each one the body above
    /// rests on through its one support face, ending with the first that rests on more or
    /// none (the column's base), at most [`MAX_COLUMN_WALK`].
    fn down_from<'a>(
        counts: &'a [u8],
        below: &'a [u32],
        top: usize,
        bodies: usize,
    ) -> impl Iterator<Item = usize> + 'a {
        let mut at = (counts.get(top) == Some(&1)).then_some(top);
        std::iter::from_fn(move || {
            let down = below[at?] as usize;
            if down == 0 || down >= bodies {
                return None;
            }
            at = (counts.get(down) == Some(&1)).then_some(down);
            Some(down)
        })
        .take(MAX_COLUMN_WALK)
    }

    /// Forgets which bodies carried a column face (before the step's are marked).
    pub fn forget_columns(&mut self) {
        self.columns_on.fill(false);
    }

    /// Marks the body at arena index `body` as carrying a column face.
    pub fn column_rests_on(&mut self, body: u32) {
        let i = body as usize;
        if self.columns_on.len() <= i {
            self.columns_on.resize(i + 1, false);
        }
        self.columns_on[i] = true;
    }

    /// Whether a column face rested on the body at arena index `body` at the end of the last
    /// step: the face it rests on is the base of that column.
    pub fn carries_column(&self, body: u32) -> bool {
        self.columns_on.get(body as usize).copied().unwrap_or(false)
    }

    /// Whether solver body `body` rests on one face at most (the static body, index 0,
    /// always does).
    pub fn single(
        &mut self,
        body: u32,
        manifolds: &[ManifoldRef],
        pairs: &[ContactPair],
        gravity: Vec3,
    ) -> bool {
        if body == 0 {
            return true;
        }
        if !self.counted {
            self.count(manifolds, pairs, gravity);
        }
        self.counts.get(body as usize).is_none_or(|&n| n <= 1)
    }

    fn count(&mut self, manifolds: &[ManifoldRef], pairs: &[ContactPair], gravity: Vec3) {
        self.counted = true;
        self.counts.clear();
        self.below.clear();
        let up = -gravity.normalize_or_zero();
        for r in manifolds {
            let Some(pair) = pairs.get(r.pair as usize) else {
                continue;
            };
            if is_support(r, pair, up) {
                let m = &pair.manifolds[r.manifold as usize];
                let (upper, lower) = upper_lower(gravity, m.normal, r.body_a, r.body_b);
                let upper = upper as usize;
                if self.counts.len() <= upper {
                    self.counts.resize(upper + 1, 0);
                    self.below.resize(upper + 1, 0);
                }
                self.counts[upper] = self.counts[upper].saturating_add(1);
                self.below[upper] = lower;
            }
        }
    }
}

/// Whether manifold `r` of `pair` is a support face: two points or more, touching, its
/// normal within [`SUPPORT_MIN_COS`] of `up` (against gravity, unit; a speculative face two
/// cubes up, or a wall, is not one).
pub(crate) fn is_support(r: &ManifoldRef, pair: &ContactPair, up: Vec3) -> bool {
    let Some(m) = pair.manifolds.get(r.manifold as usize) else {
        return false;
    };
    let touching = touching_distance(pair.size, pair.reach);
    r.count > 1
        && m.normal.dot(up).abs() > SUPPORT_MIN_COS
        && m.points.iter().any(|p| p.separation <= touching)
}
