//! The heavy-on-light treatment of resting contacts: [`support_mass_scale`] solves a light
//! body under a heavy one as if it were at most `PhysicsSettings::max_support_mass_ratio`
//! times lighter, and [`HiddenLoads`] gives the friction under that light body the share of
//! the heavy body's load the scaling keeps from it.

use glam::Vec3;

use super::column_supports::{is_support, ColumnSupports};
use crate::narrowphase::contact_pair::ContactPair;
use crate::physics_settings::PhysicsSettings;
use crate::solver::body_state::BodyState;
use crate::solver::contact_constraint::ManifoldRef;

/// How the solver takes manifold `r` (bodies as solver indices into `states`) in which a
/// dynamic body rests on one more than [`scaling_onset`] times lighter (the heavy one above
/// it along gravity, the two approaching slower than gravity's pull over one step).
///
/// Gauss–Seidel with warm starting builds a contact's impulse by about the light body's
/// momentum per substep, so a body `r` times heavier is caught only after `√r` substeps of
/// ringing: it sinks about `g·r·h²` (17 cm for 1000:1 at 240 Hz), whatever the contact's
/// stiffness. Two remedies, by what the pair rests on:
///
/// - **A column** ([`SupportMass::Column`]): where the manifold is a face (two points or
///   more) and each body rests on that one face alone (the light body on its own support),
///   the pair is solved on the true masses as a column face, and so are the faces down the
///   column under it ([`HiddenLoads::carries_heavy_column`]): the coarse correction solves
///   the light body's two faces together, exactly, their friction with them
///   (`solver::column_solve`); they stiffen for [`HEAVY_COLUMN_DEPTH_SHARE`] of the depth
///   budget (no deeper than [`HEAVY_COLUMN_RESTING_DEPTHS`]), are damped for the whole
///   column they carry and take every column pass. Momentum is kept and the
///   support carries the whole load. Scaled instead (below), the heavy body takes
///   every impulse the light one is spared, a pull and push that are not equal and
///   opposite and do work as the pair rocks: a 30 cm cube with friction on a 10 cm one
///   (27:1) rocked at 2–3 Hz and fell at fast, 1 mm ones under 3 mm and 1 cm ones fell
///   through at fast, and a 1 cm cube under a 10 cm one drifted 7 % of its size at
///   balanced; as columns each stands within 2 % (`examples/larger_on_smaller` in the
///   physics bench; before friction was in the coarse correction a light body on its true
///   mass was squeezed out from between its two friction faces, its tilt whirling).
/// - **Scaled** ([`SupportMass::Scaled`]): elsewhere (a heavy plank on two light cubes, a
///   light body resting on more than one face) the light body's inverse mass and inertia
///   are scaled so that the contact sees at most `max_support_mass_ratio`: the ringing is
///   `√(r / ratio)` times shorter. The light body then passes on less of the heavy one's
///   weight than it carries (its own support holds less than the full load: [`HiddenLoads`]
///   gives its friction the rest). Never for a frictionless pair
///   ([`ContactPair::frictionless`]), the elastic ones among them, whose energy is kept on
///   the true masses' (scaled at ratio 3, 50 elastic balls of masses up to 250:1 changed
///   their energy by 22 % at fast), and the others because the unequal impulses made a
///   frictionless 3 cm cube slide off a 1 cm one at fast.
///
/// Impacts, and light bodies on heavy ones, use the true masses ([`SupportMass::True`]).
#[inline]
pub(crate) fn support_mass_scale(
    r: &ManifoldRef,
    states: &[BodyState],
    settings: &PhysicsSettings,
    supports: &mut ColumnSupports,
    refs: &[ManifoldRef],
    pairs: &[ContactPair],
) -> SupportMass {
    let pair = &pairs[r.pair as usize];
    let (a, b) = (&states[r.body_a as usize], &states[r.body_b as usize]);
    let max_ratio = settings.max_support_mass_ratio;
    let (ia, ib) = (a.inv_mass.max_element(), b.inv_mass.max_element());
    // Most pairs: masses within the ratio, or a static or kinematic body: nothing to do
    // (tested before the onset is computed: this runs for every manifold every step).
    if !(ia > ib * max_ratio || ib > ia * max_ratio) || ia == 0.0 || ib == 0.0 {
        return SupportMass::True;
    }
    let onset = scaling_onset(settings);
    if !(ia > ib * onset || ib > ia * onset) {
        return SupportMass::True;
    }
    let gravity = settings.gravity;
    let g = gravity.length();
    if !(max_ratio >= 1.0 && g > 0.0) {
        return SupportMass::True;
    }
    let n = pair.manifolds[r.manifold as usize].normal;
    // Resting: not approaching faster than gravity's pull over a step (16 cm/s at 60 Hz).
    let approach = (Vec3::from(b.v) - Vec3::from(a.v)).dot(n);
    let b_above = gravity.dot(n) < 0.0;
    let resting = approach > -g * settings.dt;
    // The light body (larger inverse mass) must be the lower one.
    let factors = if b_above && ia > ib * max_ratio && resting {
        [ib * max_ratio / ia, 1.0]
    } else if !b_above && ib > ia * max_ratio && resting {
        [1.0, ia * max_ratio / ib]
    } else {
        return SupportMass::True;
    };
    if is_support(r, pair, -gravity / g)
        && supports.single(r.body_a, refs, pairs, gravity)
        && supports.single(r.body_b, refs, pairs, gravity)
    {
        SupportMass::Column
    } else if pair.frictionless() {
        SupportMass::True
    } else {
        SupportMass::Scaled(factors)
    }
}

/// How [`support_mass_scale`] solves a manifold.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum SupportMass {
    /// On the true masses.
    True,
    /// On the true masses, as a column face: a heavy body resting through a face on a light
    /// one, each resting on that face alone (see [`HiddenLoads::carries_heavy_column`]).
    Column,
    /// With these factors on the inverse masses and inertias of A and B.
    Scaled([f32; 2]),
}

impl SupportMass {
    /// The factors on the inverse masses and inertias of A and B.
    #[inline]
    pub(crate) fn factors(self) -> [f32; 2] {
        match self {
            Self::Scaled(f) => f,
            Self::True | Self::Column => [1.0; 2],
        }
    }
}

/// Share of the depth budget (`PhysicsSettings::max_penetration_fraction` of the smaller
/// body's size) that the faces of a heavy body's column on a light one
/// ([`SupportMass::Column`]) are stiffened to hold. The heavy body sinks through two faces,
/// each of them stiffened only as far as its load asks: at the whole budget a 1 m cube
/// 1000 times heavier than the 1 m cube under it sank 4 cm (2 cm a face) at every preset,
/// where the issue asks less than 2 cm at balanced and 1 cm at precise
/// (`tests/heavy_and_small.rs`). Bounded `(0, 1]`: at 0.25 it sank 1.0 cm, at 0.15 6 mm;
/// at 0.1 (4 mm) a 40 cm cube 1000 times heavier resting 10 cm off centre on another rocked
/// at 4 Hz and tipped over at fast, its faces too stiff for the step, while from 0.15 up it
/// stood (measured with two column passes a substep; `examples/offset_heavy`). A stiffer
/// face reaches its cap sooner (its `Softness::column_lift`); overloads are still named
/// against the whole budget. Large bodies are held further, by
/// [`HEAVY_COLUMN_RESTING_DEPTHS`].
pub const HEAVY_COLUMN_DEPTH_SHARE: f32 = 0.15;

/// Most a face of a heavy body's column may sink, in depths of a body resting alone at the
/// contact's base stiffness (`g / ω²`: 0.24 mm at the default 32 Hz between two dynamic
/// bodies, 61 µm on a static one), where that is less than [`HEAVY_COLUMN_DEPTH_SHARE`] of
/// the budget: large bodies. The bounds for a heavy body on a light one are
/// absolute (2 cm at balanced, 1 cm at precise), and at 0.15 of the budget a 10 m cube
/// 1000 times heavier than the 10 m cube under it sank 2.4 cm at balanced (two faces of
/// 3 cm budget share each; `tests/e2e/physics_presets_cli.rs`); held to 20 such depths,
/// 4.9 mm and 1.2 mm a face, it sinks 6 mm at balanced and precise (2.5 cm at fast, which
/// has no such bound). Bounded `(0, ∞)`: a 40 cm pair held to 4 (1 mm, past 0.15 of its
/// budget) rocked over at fast and at balanced when loaded 10 cm off centre
/// (`examples/offset_heavy`).
pub const HEAVY_COLUMN_RESTING_DEPTHS: f32 = 20.0;

/// Mass ratio past which [`support_mass_scale`] takes a resting pair for a heavy body's
/// column or scales it: the larger of
/// `max_support_mass_ratio` and [`ONSET_PER_SQUARED_SWEEP`] times the square of the step's
/// Gauss–Seidel sweeps (`substeps · solver_iterations`; 48 at balanced and precise, 12 at
/// fast).
///
/// A body `r` times heavier is caught after about `√r` sweeps (see [`support_mass_scale`]),
/// so up to about the square of the sweeps it is caught within the step it lands, and from
/// then on the warm-started impulse carries it (from its first step,
/// `solve_stage::NEW_FACE_STEPS`). Scaling there only did harm (measured before such pairs
/// were columns): a light body that passes on
/// less of the heavy one's weight than it carries is rocked by it, at the sizes where a
/// rocking mode is fast next to the substep. Scaled from 3:1, a 2 mm cube on a 1 mm one
/// (8:1) fell off it at balanced and precise, and a 1.5 cm or 2 cm cube on a 1 cm one
/// drifted 15-25 % of its size in 10 s at balanced; solved as they are, each holds within
/// 2 % and stays put (`tests/stacking.rs`, `a_larger_box_on_a_smaller_one_holds_and_stays_put`).
#[inline]
pub(crate) fn scaling_onset(settings: &PhysicsSettings) -> f32 {
    let sweeps = settings.substeps.saturating_mul(settings.solver_iterations) as f32;
    settings
        .max_support_mass_ratio
        .max(ONSET_PER_SQUARED_SWEEP * sweeps * sweeps)
}

/// [`scaling_onset`] over the square of the step's sweeps. Bounded `[1, ∞)`: at 1 (an onset
/// of 4:1 at fast) a 20 cm cube with friction on a 10 cm one (8:1) rocked at 3 Hz, the
/// scaled pair's unequal impulses feeding the sway, and fell at fast, as did 2 mm on 1 mm,
/// 2 cm on 1 cm and 3 mm on 1 mm at balanced and precise (27:1 past 16:1); from 2 they stand
/// (`examples/larger_on_smaller` in the physics bench: 7 → 2 of 12 fell at fast with friction,
/// 1 → 0 at balanced and precise), at 3 the same, away from the 8:1 of cubes twice the size.
/// (Past the onset such pairs were scaled then; at 8, 128:1 at balanced, a 100:1 pair of
/// 1 m cubes, solved on the true masses as a plain contact, sank 2.6 cm, past the issue's
/// 2 cm, `tests/heavy_and_small.rs`.) A pair 10:1 loaded sideways at fast holds either way.
pub const ONSET_PER_SQUARED_SWEEP: f32 = 3.0;

/// The two bodies of a manifold with normal `n` (from `a` to `b`) as (upper, lower): the one
/// above the other along `gravity` first.
#[inline]
pub(crate) fn upper_lower(gravity: Vec3, n: Vec3, a: u32, b: u32) -> (u32, u32) {
    if gravity.dot(n) < 0.0 {
        (b, a)
    } else {
        (a, b)
    }
}

/// Per solver body, the factor on the friction bound of the contacts it rests on: 1 but
/// under a light body that [`support_mass_scale`] scales (and under whatever that body
/// rests on, down to the ground); and whether it carries a heavy body's column
/// ([`HiddenLoads::carries_heavy_column`]).
///
/// Scaled by `s`, a light body takes only `s·P` of the impulse `P` the heavy body presses on
/// it, and passes only that on to its own supports: their normal impulse, and with it their
/// Coulomb bound `μ·λₙ`, misses `(1 − s)·P`. A 1 kg box under 100 kg, pushed sideways with
/// 30 % of the pair's sliding friction, slid 270 m in 2 s: its ground held
/// `μ·(1 + 10)·m·g`, not `μ·101·m·g`. The hidden load is taken from the warm-start
/// impulses (a resting load: the scaling is for resting contacts only), shared among the
/// light body's supports in proportion to their own load, and passed down through the
/// bodies below it (top first) to whatever holds the stack; each support's bound becomes
/// `μ·λₙ·(1 + hidden / carried)`, which is `μ` times the whole load at rest and falls to
/// zero with the contact's own impulse as it lifts off.
///
/// Only the friction bound is given the load. Given to the light body as a force (so that
/// its supports' rows carried it), it pressed a 1 kg box into the ground with a 1000 kg
/// load its contact, soft relative to its own mass, cannot hold, and fed back through the
/// scaled rows (a 1 kg box under 1000 kg on a gentle incline was squeezed out). What stays
/// hidden is the heavy body's moment on the light one: pushed sideways at its centre, a
/// light body under a heavy one tips once the push passes about `(1 + 2·ratio)` times its
/// weight (`ratio`: `PhysicsSettings::max_support_mass_ratio`).
#[derive(Debug, Default)]
pub(crate) struct HiddenLoads {
    /// Per solver body; empty when no contact of the step is scaled.
    factor: Vec<f32>,
    /// Scratch, kept between steps: per solver body the hidden load and the load of its own
    /// supports, and the supports as (upper body's height, upper, lower, load).
    hidden: Vec<f32>,
    carried: Vec<f32>,
    supports: Vec<(f32, u32, u32, f32)>,
    /// Per solver body, whether a heavy body rests on it as a column
    /// ([`SupportMass::Column`]), or on a body it holds up down its column; empty when none
    /// does.
    carries_heavy_column: Vec<bool>,
}

impl HiddenLoads {
    /// Every factor 1 (a step where no awake body is [`scaling_onset`] times heavier than
    /// another).
    pub(crate) fn clear(&mut self) {
        self.factor.clear();
        self.carries_heavy_column.clear();
    }

    /// Over the step's manifolds `refs` (bodies as solver indices into `states`), with the
    /// warm-start impulses in `pairs`; `height(i)` is solver body `i`'s position against
    /// gravity.
    pub(crate) fn update(
        &mut self,
        refs: &[ManifoldRef],
        pairs: &[ContactPair],
        states: &[BodyState],
        settings: &PhysicsSettings,
        columns: &mut ColumnSupports,
        height: impl Fn(u32) -> f32,
    ) {
        self.factor.clear();
        self.carries_heavy_column.clear();
        // A manifold's warm-started load (an impact's impulse is not one).
        let load = |r: &ManifoldRef| -> f32 {
            let m = &pairs[r.pair as usize].manifolds[r.manifold as usize];
            m.points
                .iter()
                .take(usize::from(r.count))
                .filter(|p| !p.impact)
                .map(|p| p.normal_impulse.max(0.0))
                .sum()
        };
        let hidden = &mut self.hidden;
        hidden.clear();
        hidden.resize(states.len(), 0.0);
        let mut any = false;
        for r in refs {
            let support = support_mass_scale(r, states, settings, columns, refs, pairs);
            if support == SupportMass::Column {
                let normal = pairs[r.pair as usize].manifolds[r.manifold as usize].normal;
                let (_, lower) = upper_lower(settings.gravity, normal, r.body_a, r.body_b);
                if self.carries_heavy_column.is_empty() {
                    self.carries_heavy_column.resize(states.len(), false);
                }
                self.carries_heavy_column[lower as usize] = true;
                // And the bodies it rests on down its column, which carry the heavy body
                // too.
                for below in
                    columns.column_below(lower, refs, pairs, settings.gravity, states.len())
                {
                    self.carries_heavy_column[below] = true;
                }
            }
            for (s, body) in support.factors().into_iter().zip([r.body_a, r.body_b]) {
                if s < 1.0 {
                    hidden[body as usize] += (1.0 - s) * load(r);
                    any = true;
                }
            }
        }
        if !any {
            return;
        }
        // Every dynamic body's supports (the manifolds it rests on, the other body below it
        // along gravity), with their load.
        let dynamic = |i: u32| states[i as usize].inv_mass.max_element() > 0.0;
        let (carried, supports) = (&mut self.carried, &mut self.supports);
        carried.clear();
        carried.resize(states.len(), 0.0);
        supports.clear();
        for r in refs {
            let normal = pairs[r.pair as usize].manifolds[r.manifold as usize].normal;
            let (upper, lower) = upper_lower(settings.gravity, normal, r.body_a, r.body_b);
            let p = load(r);
            if dynamic(upper) && p > 0.0 {
                carried[upper as usize] += p;
                supports.push((height(upper), upper, lower, p));
            }
        }
        // Top first: a body's hidden load is whole before it is shared among its supports.
        supports.sort_by(|x, y| y.0.total_cmp(&x.0));
        for &(_, upper, lower, p) in supports.iter() {
            let (u, l) = (upper as usize, lower as usize);
            if hidden[u] > 0.0 && dynamic(lower) {
                hidden[l] += hidden[u] * p / carried[u];
            }
        }
        self.factor
            .extend(hidden.iter().zip(carried.iter()).map(|(&h, &c)| {
                if h > 0.0 && c > 0.0 {
                    1.0 + h / c
                } else {
                    1.0
                }
            }));
    }

    /// Whether solver body `body` carries a heavy body's column ([`SupportMass::Column`]):
    /// the heavy body rests on it, or on a body it holds up through one face each. The face
    /// `body` rests on is a face of that column.
    #[inline]
    pub(crate) fn carries_heavy_column(&self, body: u32) -> bool {
        self.carries_heavy_column
            .get(body as usize)
            .copied()
            .unwrap_or(false)
    }

    /// The factor on the friction bound of the contacts solver body `body` rests on.
    #[inline]
    pub(crate) fn factor(&self, body: u32) -> f32 {
        self.factor.get(body as usize).copied().unwrap_or(1.0)
    }
}

/// A body is pinched when a body more than this many times heavier rests on it through a
/// face: the faces it rests on are not levelled (see [`PinchedBodies`]). Bounded `(1, ∞)`:
/// the columns it is for have each cube under one 3.4–8 times heavier; at 2 and 3 they
/// stand alike, and every column and pyramid of `tests/stacking.rs` with them.
pub const PINCHED_MASS_RATIO: f32 = 3.0;

/// Per solver body, whether it is pinched: a dynamic body more than [`PINCHED_MASS_RATIO`]
/// times heavier rests on it through a face (two points or more). The faces with friction
/// such a body rests on are not levelled (their `ContactConstraint::load_level_share` is 0,
/// as a column face and as one loaded past its tilt limit).
///
/// Levelled, a face is stiff in tilt; a light body between a levelled face under it and the
/// face of a heavy body on it has its tilt held stiffly from both sides, far stiffer than its
/// own small inertia, and at one iteration a step the pair over-corrected: the light body's
/// tilt changed sign every step and doubled every two (a 1 cm cube with friction under a 4 cm
/// one, solved on the true masses, was squeezed out within half a second at balanced; a
/// column of 1, 2 and 3 mm cubes and one of 3, 6 and 9 mm cubes fell at balanced). Not
/// levelled, its support face is as soft in tilt as its depth, and the column stands
/// (`tests/stacking.rs`, `a_larger_box_on_a_smaller_one_holds_and_stays_put`).
#[derive(Debug, Default)]
pub(crate) struct PinchedBodies {
    /// Per solver body; empty when no body of the step is pinched.
    pinched: Vec<bool>,
}

impl PinchedBodies {
    /// None pinched (a step where no awake body is [`PINCHED_MASS_RATIO`] times heavier
    /// than another).
    pub(crate) fn clear(&mut self) {
        self.pinched.clear();
    }

    /// Over the step's manifolds `refs` (bodies as solver indices into `states`).
    pub(crate) fn update(
        &mut self,
        refs: &[ManifoldRef],
        pairs: &[ContactPair],
        states: &[BodyState],
        gravity: Vec3,
    ) {
        self.pinched.clear();
        let inv_mass = |i: u32| states[i as usize].inv_mass.max_element();
        for r in refs.iter().filter(|r| r.count >= 2) {
            let normal = pairs[r.pair as usize].manifolds[r.manifold as usize].normal;
            let (upper, lower) = upper_lower(gravity, normal, r.body_a, r.body_b);
            let (iu, il) = (inv_mass(upper), inv_mass(lower));
            if iu > 0.0 && il > iu * PINCHED_MASS_RATIO {
                if self.pinched.is_empty() {
                    self.pinched.resize(states.len(), false);
                }
                self.pinched[lower as usize] = true;
            }
        }
    }

    /// Whether solver body `body` is pinched.
    #[inline]
    pub(crate) fn get(&self, body: u32) -> bool {
        self.pinched.get(body as usize).copied().unwrap_or(false)
    }
}
