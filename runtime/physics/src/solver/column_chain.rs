//! [`ChainFace`]: how much a face of a column must be levelled so that the column stands,
//! from the chain of faces it is one of.
//!
//! A face's tilt stiffness grows with its load (its depth budget stiffens it), so each face
//! of a column holds the bodies above it; but the faces of a column are tilt springs in
//! series under the load above them, and the chain is weaker than each of its links. Ten
//! equal cubes of 5–30 cm, every other one 10–30 % aside, whose faces were levelled for
//! their own loads only (`contact_batch::levelled_for_load`), leaned over within 10 s at
//! 60 Hz × 4 and 120 Hz × 4 (four and three of 27); twenty 1 m boxes at 60 Hz × 4 fell
//! within 50 s. A levelled face leaks its patch's mean impulse in part instead of each
//! point's own (`FaceContact::level_patch`): a share `s` of the leak makes it `1 / (1 − s)`
//! times as stiff in tilt and no stiffer in depth.

use super::contact_batch::{COLUMN_STIFFNESS, LEVEL_SHARE};

/// The squared length, in bodies, of the longest column of equal bodies that soft faces hold
/// upright, per unit of `ω²·size / (g·ratio)` of its faces (see [`ChainFace`]). From the
/// chain's stiffness matrix: `n` rigid blocks of height `s` on tilt springs `k_i` under the
/// weight above them, faces at `k_i/(W_i·s) = c` (each face stiffened for its own load, as
/// the depth budget does) lose their last stable mode at `n² ≈ 5.5·c` (fitted from `c` = 5 to
/// 200), and `k/(W·s) = ω²·s / (4·g·ratio)` for a face as wide as the bodies are high.
pub const CHAIN_CRITICAL: f32 = 5.5 / 4.0;

/// How far inside its critical length ([`CHAIN_CRITICAL`]) a column's faces are made to
/// hold it. Bounded `[1, ∞)`: the chain's sum leaves out the offsets of a zig-zag column,
/// the damping and the iterations. Of the 63 zig-zag columns with friction of
/// `examples/offset_stacks.rs` in the physics bench (5 mm–1 m, ten high at most), at 6 none
/// and one drifted past 1 % of a cube after settling at 60 Hz × 4 and 120 Hz × 4 (1.3 %;
/// rapier 12 and 11, up to 295 %); at 1.5 and 2 ten-high columns fell, at 4 one drifted at
/// each (1.4 % and 1.7 %), at 16 and 32 columns of 1 cm cubes, levelled past need, fell.
/// At 8 and 12 none drifted at either (and at 8, 10 instead of 13 at 30 Hz × 2), but at 8
/// the 100-row pyramid at 60 Hz × 4 slumped 0.630 m instead of 0.607 (rapier 0.682) at 8 %
/// more cost, and the 20-box stack cost 24 % more.
pub const CHAIN_MARGIN: f32 = 6.0;

/// The most of a column face's leak that is the patch's mean impulse (see
/// [`ChainFace::column_level_share`]). Bounded `(LEVEL_SHARE, 1)`: at 1 a face has no leak in
/// tilt at all (see [`LEVEL_SHARE`]); at 0.9 forty 1 m cubes at 30 Hz × 2 leaned half a
/// metre within 35 s; at 0.95 and 0.99 they stand.
pub const COLUMN_MAX_LEVEL_SHARE: f32 = 0.95;

/// `h·ω` of a column face's stiffness in tilt once levelled (a share `s` stiffens it
/// `1 / (1 − s)` times, `h·ω` by `1 / √(1 − s)`) past which it is levelled no further than
/// [`LEVEL_SHARE`] (see [`ChainFace::column_level_share`]). Bounded `(0, ∞)`: at 12 forty 1 m
/// cubes at 30 Hz × 2 fell (their ground face, at `h·ω` π, levelled at most 0.93); with no
/// bound ten 1 cm cubes at 30 Hz × 2 (faces at `h·ω` 12.6, levelled 0.83–0.89) fell within
/// 10 s; from 16 to 20 both stand.
pub const COLUMN_MAX_TILT_STIFFNESS: f32 = 16.0;

/// A face between bodies that rest on one face each, in the column they make (a frictionless
/// face is levelled at `LEVEL_SHARE` anyway, and asks only [`ChainFace::needs_column`]).
#[derive(Clone, Copy, Debug)]
pub struct ChainFace {
    /// Bodies in the column (`ColumnSupports::column_length`).
    pub length: f32,
    /// The face's load over its own effective mass's weight.
    pub load_ratio: f32,
    /// The face's stiffness, Hz.
    pub hertz: f32,
    /// The size of its pair, m.
    pub size: f32,
    /// Gravity, m/s².
    pub g: f32,
    /// The substep, s.
    pub h: f32,
}

impl ChainFace {
    /// The share of the face's leak its chain needs levelled: none where the chain of its
    /// faces, soft in tilt, is within [`CHAIN_MARGIN`] of holding the column
    /// ([`CHAIN_CRITICAL`]), else the share that makes the face as much stiffer in tilt as it
    /// needs (`1 − held/needed`). Never without gravity.
    fn need(&self) -> f32 {
        let omega = 2.0 * std::f32::consts::PI * self.hertz;
        let held = CHAIN_CRITICAL * omega * omega * self.size;
        let needed = CHAIN_MARGIN * self.length * self.length * self.load_ratio * self.g;
        if self.g <= 0.0 || self.load_ratio <= 0.0 || needed <= held {
            return 0.0;
        }
        1.0 - held / needed
    }

    /// `h·ω` of the face's stiffness.
    fn stiffness(&self) -> f32 {
        self.h * 2.0 * std::f32::consts::PI * self.hertz
    }

    /// The most of its leak one iteration a substep converges levelled, up to
    /// [`LEVEL_SHARE`]: its levelled tilt within `COLUMN_STIFFNESS`. Uncapped, a stack of
    /// twenty 1 m boxes at 60 Hz × 2 fell, 3.1 m instead of 7 mm.
    fn converged(&self) -> f32 {
        (1.0 - (self.stiffness() / COLUMN_STIFFNESS).powi(2)).min(LEVEL_SHARE)
    }

    /// How much of the face's leak is the patch's mean impulse, in no column face: what its
    /// chain needs ([`Self::need`]), as far as one iteration a substep converges.
    #[must_use]
    pub fn level_share(&self) -> f32 {
        self.need().min(self.converged()).max(0.0)
    }

    /// Whether the chain needs more levelling than one iteration a substep converges: then
    /// the face is a column face, levelled as its chain needs and solved with its column as
    /// a whole ([`Self::column_level_share`], `ColumnSolve`). Levelled only as far as the
    /// iteration converges, twenty 1 m boxes at 60 Hz × 4 fell within 50 s, and twenty 10 cm
    /// and 30 cm cubes at 120 Hz × 4 within 10 s and 30 s (rapier holds them, rocking a few
    /// % of a cube); as column faces all stand (`examples/tall_stack.rs` in the physics
    /// bench).
    #[must_use]
    pub fn needs_column(&self) -> bool {
        let need = self.need();
        need > 0.0 && need > self.converged()
    }

    /// How much of a column face's leak is the patch's mean impulse, at its stiffness as a
    /// column face: [`LEVEL_SHARE`], or more where the chain needs it, up to
    /// [`COLUMN_MAX_LEVEL_SHARE`] and while its tilt stays within
    /// [`COLUMN_MAX_TILT_STIFFNESS`]. The column is solved as a whole (`ColumnSolve`), so
    /// unlike a face in no column its share is not held to what one iteration converges. At
    /// [`LEVEL_SHARE`] alone, a stack of twenty 1 m boxes at 30 Hz × 2, every face a column
    /// face, leaned over in a tilt that doubled every 2 s and fell within 40 s (its faces,
    /// stiffened for their loads, each at `k/(W·s)` ≈ 50: a chain of about 17 holds).
    #[must_use]
    pub fn column_level_share(&self) -> f32 {
        let tilt = 1.0 - (self.stiffness() / COLUMN_MAX_TILT_STIFFNESS).powi(2);
        self.need()
            .min(COLUMN_MAX_LEVEL_SHARE)
            .min(tilt)
            .max(LEVEL_SHARE)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn face(length: f32, hertz: f32) -> ChainFace {
        // Twenty 1 m boxes' middle face at 60 Hz × 4: the weight of ten above it, a
        // reduced-mass ratio of 20.
        ChainFace {
            length,
            load_ratio: 20.0,
            hertz,
            size: 1.0,
            g: 9.81,
            h: 1.0 / 240.0,
        }
    }

    #[test]
    fn a_short_column_needs_no_levelling_and_a_long_one_more_than_converges() {
        // Two boxes hold on their own faces.
        let short = face(2.0, 32.0);
        assert_eq!(short.level_share(), 0.0);
        assert!(!short.needs_column());
        // Twenty need more than one iteration converges (h·ω 0.84: at most 0.30).
        let tall = face(20.0, 32.0);
        assert!(tall.needs_column());
        assert!((tall.level_share() - tall.converged()).abs() < 1e-6);
        assert!(tall.level_share() < 0.31);
        // As a column face it gets what it needs, between the bounds.
        let share = tall.column_level_share();
        assert!(
            (LEVEL_SHARE..=COLUMN_MAX_LEVEL_SHARE).contains(&share),
            "{share}"
        );
        // None without gravity.
        assert_eq!(ChainFace { g: 0.0, ..tall }.level_share(), 0.0);
    }

    #[test]
    fn a_stiff_column_face_is_levelled_no_further_than_its_tilt_allows() {
        // A 1 cm cube's face at 120 Hz at 30 Hz × 2 (h·ω 12.6): its tilt bound is below
        // LEVEL_SHARE, which it keeps.
        let stiff = ChainFace {
            length: 10.0,
            load_ratio: 18.0,
            hertz: 120.0,
            size: 0.01,
            g: 9.81,
            h: 1.0 / 60.0,
        };
        assert!(stiff.need() > LEVEL_SHARE);
        assert_eq!(stiff.column_level_share(), LEVEL_SHARE);
    }
}
