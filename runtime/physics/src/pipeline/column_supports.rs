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
/// Only a face the depth budget stiffens past `COLUMN_STIFFNESS` asks (or one at the base
/// rate under a column, `Self::carries_column`), which nearly no scene has: counted for
/// every manifold every step, this cost the 20-row pyramid about 1 %.
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
                let mut at = top;
                for _ in 0..MAX_COLUMN_WALK {
                    let down = self.below[at] as usize;
                    if down == 0 || down >= states.len() {
                        break;
                    }
                    self.column_masses[down] += mass;
                    if self.counts.get(down) != Some(&1) {
                        break;
                    }
                    at = down;
                }
            }
        }
        self.column_masses
            .get(body as usize)
            .copied()
            .unwrap_or(0.0)
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
            let Some(m) = pair.manifolds.get(r.manifold as usize) else {
                continue;
            };
            let touching = touching_distance(pair.size, pair.reach);
            if r.count > 1
                && m.normal.dot(up).abs() > SUPPORT_MIN_COS
                && m.points.iter().any(|p| p.separation <= touching)
            {
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
