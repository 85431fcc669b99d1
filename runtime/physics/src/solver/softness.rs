//! [`Softness`]: soft-constraint coefficients (mass-spring-damper) for one substep size.

/// Load stiffening never goes above this fraction of the substep rate, 1/s per Hz (above it
/// the bench's 20-row pyramid jitters apart at 2 substeps).
pub const LOAD_STIFFENING_MAX_SUBSTEP_FRACTION: f32 = 0.125;

/// … nor above this fraction of the step rate (contact geometry is refreshed once per step;
/// stiffer contacts than this made the pyramid jitter apart at 60 Hz × 4).
pub const LOAD_STIFFENING_MAX_STEP_FRACTION: f32 = 0.5;

/// Load stiffening of a contact between two balls goes up to this fraction of the substep
/// rate, 1/s per Hz: twice [`LOAD_STIFFENING_MAX_SUBSTEP_FRACTION`]. A ball pair's one point
/// lies on the line of centres, is regenerated every step and moves with the centres only,
/// which the solver's linearised separation tracks exactly within the step; the caps above
/// guard against the error of faces that turn within the step (the 20-row pyramid jitters
/// apart past them), which a ball pair does not have. With it the 8,000 poured spheres at
/// 60 Hz × 4 press into each other 1.22 cm deep instead of 3.05 cm (mean of five starts;
/// rapier 2.80 cm), and no other benchmark figure moves.
pub const BALL_LOAD_STIFFENING_MAX_SUBSTEP_FRACTION: f32 = 0.25;

/// … and up to this fraction of the step rate: twice [`LOAD_STIFFENING_MAX_STEP_FRACTION`].
pub const BALL_LOAD_STIFFENING_MAX_STEP_FRACTION: f32 = 1.0;

/// Size stiffening never goes above this fraction of the substep rate, 1/s per Hz (`h·ω`
/// up to 2π). Bounded `(0, ∞)`: the soft step stays stable for any stiffness, but past about
/// one substep per period a contact is as good as rigid and a stiffer one only adds
/// rounding; below it heavy loads on small bodies sink further.
pub const SIZE_STIFFENING_MAX_SUBSTEP_FRACTION: f32 = 1.0;

/// Half-life of a contact's load memory, seconds: a contact stiffens for the largest load
/// it carried recently, not last step's (stiffening from last step's load alone fed back:
/// a 100:1 box pressed in, stiffened, shot out, unloaded, went soft and fell back in,
/// deeper each time). Bounded `[dt, ∞)`: shorter brings the feedback back, longer keeps
/// contacts stiff after their load is gone.
pub const LOAD_MEMORY_HALF_LIFE: f32 = 0.5;

/// … nor above this fraction of the step rate, 1/s per Hz: contact geometry is refreshed
/// once per step, and a column of ten boxes at 30 Hz × 2 stiffened to 60 Hz gained energy
/// from it and burst.
pub const SIZE_STIFFENING_MAX_STEP_FRACTION: f32 = 1.5;

/// A settled column face (see `contact_batch::COLUMN_SETTLE_STEPS`) may stiffen up to this
/// fraction of the substep rate, 1/s per Hz (`h·ω` up to 4π), past the step's cap
/// ([`SIZE_STIFFENING_MAX_STEP_FRACTION`]), times its [`Softness::column_lift`]: resting,
/// its geometry does not turn within the step, and its column is solved as a whole
/// (`solve::COLUMN_PASSES`, `column_solve`). Bounded `(0, ∞)`: it only lifts the cap, and a
/// face stiffens no further than its depth budget asks. At 60 Hz × 4, 0.5 left five 1 mm
/// cubes 14 % deep and ten 3 mm ones 10 %, and 1 left ten 1 mm cubes 7.8 % deep (the face
/// under nine cubes of its own mass needs about twice the substep rate for the 2 % budget);
/// from 2 every column of 1 mm–10 m cubes of `tests/stacking.rs` settles at the budget, the
/// same at 4, but from 4 columns of ten 5 mm cubes zig-zag at fast fell
/// (`examples/offset_stacks` in the physics bench). (Without the coarse correction, 0.7 and
/// more no longer converged the column: ten 3 mm cubes sank 19 % or fell.)
pub const COLUMN_MAX_SUBSTEP_FRACTION: f32 = 2.0;

/// Most [`Softness::column_lift`] multiplies a column face's cap by: `h·ω` up to 32π, where
/// the soft row is rigid to 10⁻⁴. Bounded `[1, ∞)`: at 1 a frictionless 10 cm cube on a 1 cm
/// one (1000:1, solved on the true masses: see `heavy_on_light::support_mass_scale`) sank
/// 10.8 % of the small cube at balanced and 60 % at fast; at 4 2.0 % at balanced and 10.8 %
/// at fast, at 8 2.0 % at balanced and precise and 2.7 % at fast.
pub const MAX_COLUMN_LIFT: f32 = 8.0;

/// Coefficients of a soft constraint with stiffness `hertz` and damping ratio `zeta`
/// at substep `h` (Box2D v3 / "soft step" formulation):
/// `ω = 2π·hertz`, `a1 = 2ζ + hω`, `a2 = hω·a1`, `a3 = 1/(1 + a2)`,
/// `bias_rate = ω / a1`, `mass_scale = a2·a3`, `impulse_scale = a3`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Softness {
    /// Converts position error (m) into a velocity bias (m/s), 1/s.
    pub bias_rate: f32,
    /// Scales the effective mass (< 1 makes the constraint soft).
    pub mass_scale: f32,
    /// Scales the accumulated impulse fed back (leak that keeps the spring stable).
    pub impulse_scale: f32,
}

impl Default for Softness {
    /// [`Softness::RIGID`].
    fn default() -> Self {
        Self::RIGID
    }
}

impl Softness {
    /// Rigid constraint (no bias, full mass).
    pub const RIGID: Self = Self {
        bias_rate: 0.0,
        mass_scale: 1.0,
        impulse_scale: 0.0,
    };

    /// Builds the coefficients; `hertz <= 0` gives [`Softness::RIGID`].
    #[must_use]
    pub fn new(hertz: f32, zeta: f32, h: f32) -> Self {
        if hertz <= 0.0 {
            return Self::RIGID;
        }
        let omega = 2.0 * std::f32::consts::PI * hertz;
        let a1 = 2.0 * zeta + h * omega;
        let a2 = h * omega * a1;
        let a3 = 1.0 / (1.0 + a2);
        Self {
            bias_rate: omega / a1,
            mass_scale: a2 * a3,
            impulse_scale: a3,
        }
    }

    /// A contact at `hertz` that carries `mass_ratio` times its own effective mass (a heavy
    /// body on a light one): the damping ratio grows with the square root of the ratio,
    /// `ζ · √mass_ratio`.
    ///
    /// A soft row's stiffness and damping are relative to the contact's effective mass, the
    /// light body's; the mass it holds up is `mass_ratio` times that, and left at ratio `ζ`
    /// the row damps it only `ζ / √mass_ratio` (a 1000:1 box rang on its support, ten times
    /// the static deflection deep, and bounced off). Scaled, the supported mass is damped
    /// like an unloaded contact damps its own; the static deflection, `a / ω²`, does not
    /// depend on the damping, and overlap is pushed out no faster than by a light contact.
    #[must_use]
    pub fn for_supported_mass(hertz: f32, zeta: f32, h: f32, mass_ratio: f32) -> Self {
        Self::new(hertz, zeta * mass_ratio.max(1.0).sqrt(), h)
    }

    /// Stiffest contact, Hz, that [`Softness::for_load`] may reach at substep `h` and step
    /// `dt`: `min(h⁻¹ · 0.125, dt⁻¹ · 0.5)` (see the two constants).
    #[must_use]
    pub fn max_load_hertz(h: f32, dt: f32) -> f32 {
        (LOAD_STIFFENING_MAX_SUBSTEP_FRACTION / h).min(LOAD_STIFFENING_MAX_STEP_FRACTION / dt)
    }

    /// [`Softness::max_load_hertz`] for a contact between two balls:
    /// `min(h⁻¹ · 0.25, dt⁻¹ · 1.0)` (see the two ball constants).
    #[must_use]
    pub fn max_ball_load_hertz(h: f32, dt: f32) -> f32 {
        (BALL_LOAD_STIFFENING_MAX_SUBSTEP_FRACTION / h)
            .min(BALL_LOAD_STIFFENING_MAX_STEP_FRACTION / dt)
    }

    /// Contact softness scaled to the load it carries. `load_ratio` is the contact's
    /// warm-started normal impulse over the impulse its own effective mass would need against
    /// gravity (`Σλ / Σ(m_eff · g · h)`): about 1 for a body resting alone, 19 under the
    /// bottom box of a 20-box stack, 200 under a light cube holding a 400× heavier plank. The
    /// stiffness grows with `√ratio` so that loaded contacts deflect about as much as a body
    /// resting alone (`g / ω²`) instead of `ratio` times more, capped at `max_hertz` (never
    /// below `base_hertz`).
    #[must_use]
    pub fn for_load(base_hertz: f32, load_ratio: f32, max_hertz: f32, zeta: f32, h: f32) -> Self {
        Self::new(Self::load_hertz(base_hertz, load_ratio, max_hertz), zeta, h)
    }

    /// The stiffness of [`Softness::for_load`], Hz.
    #[must_use]
    pub fn load_hertz(base_hertz: f32, load_ratio: f32, max_hertz: f32) -> f32 {
        (base_hertz * load_ratio.max(1.0).sqrt()).min(max_hertz.max(base_hertz))
    }

    /// Stiffness, Hz, at which a contact carrying load acceleration `load_accel` (m/s²: its
    /// normal impulse over its effective mass and the substep) deflects `budget` metres:
    /// the static deflection of the soft contact is `a / ω²`, so `ω = √(a / budget)`.
    #[must_use]
    pub fn size_hertz(load_accel: f32, budget: f32) -> f32 {
        if load_accel > 0.0 && budget > 0.0 {
            (load_accel / budget).sqrt() / (2.0 * std::f32::consts::PI)
        } else {
            0.0
        }
    }

    /// Stiffest contact, Hz, that size stiffening may reach at substep `h` and step `dt`:
    /// `min(h⁻¹ · 1, dt⁻¹ · 1.5)` (see the two constants).
    #[must_use]
    pub fn max_size_hertz(h: f32, dt: f32) -> f32 {
        (SIZE_STIFFENING_MAX_SUBSTEP_FRACTION / h).min(SIZE_STIFFENING_MAX_STEP_FRACTION / dt)
    }

    /// Stiffest a settled column face with [`Softness::column_lift`] `lift` may be, Hz:
    /// [`Softness::max_size_hertz`] or `lift · h⁻¹ · 2` ([`COLUMN_MAX_SUBSTEP_FRACTION`]),
    /// whichever is stiffer.
    #[must_use]
    pub fn max_column_hertz(h: f32, dt: f32, lift: f32) -> f32 {
        Self::max_size_hertz(h, dt).max(lift * COLUMN_MAX_SUBSTEP_FRACTION / h)
    }

    /// How far past [`COLUMN_MAX_SUBSTEP_FRACTION`] a column face may stiffen: the square
    /// root of the load it carries per body of its column of `column_length` bodies,
    /// `√(load_ratio / (2·length))`, in `[1, MAX_COLUMN_LIFT]`. A face's stiffness for its
    /// budget grows with the square root of its load (`load_ratio`, in weights of its own
    /// effective mass); the cap holds a column of equal bodies, whose faces carry up to two
    /// such weights per body of the column (a face between two bodies has their reduced
    /// mass), and is lifted where a body is far heavier than the one under it: a 10 cm cube
    /// on a 1 cm one loads both faces about 1000 times the small cube's weight in a column
    /// of two (lift 8). (Over a static base a face carries one weight per body; lifted from
    /// there, a 1 mm cube with friction under a 2 mm one fell at fast.)
    #[must_use]
    pub fn column_lift(load_ratio: f32, column_length: u16) -> f32 {
        let per_body = load_ratio / (2.0 * f32::from(column_length.max(1)));
        per_body.max(1.0).sqrt().min(MAX_COLUMN_LIFT)
    }
}
