//! [`PhysicsSettings`]: every tunable of the simulation, with units and costs.

use glam::Vec3;

use crate::settings_error::SettingsError;

/// Simulation settings. Each field states its unit, its default (the line
/// `Default: ` is checked against [`PhysicsSettings::default`] by a test) and what
/// too high / too low does. With the `serde` feature, a partial description fills the
/// missing fields from [`PhysicsSettings::default`]; check what was read with
/// [`PhysicsSettings::validate`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(default, deny_unknown_fields))]
pub struct PhysicsSettings {
    /// Step length, seconds.
    /// Default: `1/60`
    /// Too high: tunnelling, stiff stacks wobble, less accurate trajectories.
    /// Too low: more CPU per simulated second.
    pub dt: f32,
    /// Global gravity, m/s².
    /// Default: `(0, -9.81, 0)`
    pub gravity: Vec3,
    /// Substeps per step (soft step: integrate, solve, relax each substep).
    /// Default: `4`
    /// Too high: CPU cost grows linearly. Too low (1): stacks sink and jitter, heavy-on-light
    /// contacts get soft.
    pub substeps: u32,
    /// Biased solver passes per substep.
    /// Default: `1`
    /// Too high: CPU cost. Too low: not applicable (minimum 1).
    pub solver_iterations: u32,
    /// Relax passes per substep (remove the position-correction velocity so correction adds
    /// no energy).
    /// Default: `1`
    /// Too high: CPU cost. Too low (0): push-out velocity stays in bodies (popping).
    pub relax_iterations: u32,
    /// Contact stiffness, Hz (clamped to a quarter of the substep rate; contacts with a
    /// static body get twice this).
    /// Default: `32` (measured: the 20-row pyramid at 60 Hz × 4 stays steady up to 35 Hz
    /// and jitters from 40 Hz; 32 leaves a margin and sinks an 8,000-sphere pile 2.3 cm
    /// instead of 2.8 cm at 30 Hz)
    /// Too high: stiff, may ring at low substep counts. Too low: squishy, visible sinking.
    pub contact_hertz: f32,
    /// Contact damping ratio (dimensionless).
    /// Default: `5` (rapier's; Box2D's 10 over-damps the push-out: piles and stacks settled
    /// deeper and drifted more in the bench)
    /// Too high: sluggish push-out. Too low: bouncy correction.
    pub contact_damping_ratio: f32,
    /// Fastest speed at which overlap is pushed apart, m/s.
    /// Default: `3`
    /// Too high: deep overlaps explode apart. Too low: deep overlaps resolve slowly.
    pub max_contact_push_speed: f32,
    /// Penetration budget of a resting contact, as a fraction of the smallest dimension of
    /// the smaller body (a sphere's diameter, a box's shortest side). A contact whose load
    /// would press it deeper stiffens until its static deflection fits (up to a stiffness of
    /// one period per substep); where even that is not enough (a heavy load on a small
    /// body at a coarse step) the contact is named in `StepOutput::overloaded_contacts`.
    /// Default: `0.02` (two such contacts in a chain stay under 5 % of the body's size)
    /// Too high: small bodies and heavily loaded ones visibly sink into each other. Too low:
    /// more contacts run at the stiffness cap, where stacks and piles ring a little more.
    pub max_penetration_fraction: f32,
    /// Largest mass ratio a resting contact between two dynamic bodies is solved with: the
    /// lighter body's inverse mass is scaled down in that contact so that it looks at most
    /// this many times lighter (see `pipeline/heavy_on_light.rs`). Only pairs with friction
    /// past the larger of this and `3 · (substeps · solver_iterations)²` (48 at balanced and
    /// precise, 12 at fast) are scaled: Gauss–Seidel catches a lighter ratio within its step,
    /// and scaling it rocks a small light body (a 2 mm cube on a 1 mm one fell). A heavy body
    /// resting through a face on a light one, each on that one face, is not scaled but
    /// solved on the true masses as a column (past the same ratio, and not with 0); impacts,
    /// elastic and frictionless pairs use the true masses; the friction under a scaled light
    /// body is given the load the scaling keeps from it.
    /// Default: `3`
    /// Too high (or 0, off): a heavy body on a light one rings into it for `√ratio`
    /// substeps and sinks about `g·ratio·h²` (17 cm for 1000:1 at balanced), and at fast an
    /// off-centre load from 10× the light body's mass up tips the pair over (at 10, a 1 cm
    /// offset tilted it 0.18 rad and a 6 cm one fell). Too low: the light body feels less of
    /// the heavy one's moment, and tips under a sideways push at its centre past about
    /// `(1 + 2·ratio)` times its own weight (open, see `tests/heavy_and_small.rs`).
    pub max_support_mass_ratio: f32,
    /// Contact distance tolerance, metres: the CCD stop distance and the hysteresis for
    /// ending contact events. (The solver has no penetration dead zone: resting bodies sink
    /// only by the soft contact's static deflection, ~0.07 mm on the ground at defaults.)
    /// Default: `0.001`
    /// Too high: CCD stops bodies visibly short of walls. Too low: contact events flicker
    /// and CCD hits land in contact.
    pub linear_slop: f32,
    /// Contacts closer than this are generated ahead of touching (speculative), metres.
    /// Default: `0.02`
    /// Too high: ghost collisions near edges. Too low: fast bodies overlap before contact.
    pub speculative_distance: f32,
    /// Cap on the extra speculative distance from relative velocity, metres (the distance is
    /// `speculative_distance + |v_rel| · dt`, capped by this). Bodies with CCD too: past the
    /// cap their time of impact stops them, and the contact takes over at the next step. A
    /// speculative contact as long as a bullet's step was a ghost: a 2 cm bullet at 300 m/s
    /// passing 5 cm beside a box resting against a wall knocked it spinning at 190 rad/s.
    /// Default: `0.5`
    /// Too high: costly pairs for fast bodies, ghost contacts. Too low: falling bodies
    /// overlap the ground at impact.
    pub max_speculative_distance: f32,
    /// Enlargement of broadphase boxes, metres (at most a quarter of the collider's smallest
    /// half extent, so small bodies do not collect far neighbours).
    /// Default: `0.1`
    /// Too high: many pairs that never touch. Too low: tree updates every step.
    pub aabb_margin: f32,
    /// Impact speed (normal approach at the moment of contact, see
    /// [`crate::solver::restitution`]) at or below which a contact does not bounce, m/s.
    /// Approaches no faster than one substep of gravity never bounce (that is how resting
    /// looks to the integrator), so 0 is safe: every real impact bounces.
    /// Default: `0.1` (a ball stops bouncing once its rebounds are below 0.5 mm)
    /// Too high: small bounces die (at 1 m/s, two e = 1 balls meeting at 0.5 m/s stick
    /// together). Too low: bouncy bodies take longer to come to rest (each bounce is real).
    pub restitution_threshold: f32,
    /// Tangential speed below which a contact uses static friction, m/s.
    /// Default: `0.05`
    /// Too high: sliding bodies stop too early. Too low: static friction rarely applies.
    pub static_friction_speed: f32,
    /// Speed cap, m/s: a body's linear speed is clamped to it before every substep's motion.
    /// The first time a body is clamped it is named in `StepOutput::speed_caps` (once per
    /// body and cap), so a host can say so.
    /// Default: `1000`
    /// Too high: a blow-up can throw bodies very far. Too low: fast projectiles are slowed.
    pub max_linear_speed: f32,
    /// Spin cap, rad/s, clamped and reported like `max_linear_speed`.
    /// Default: `200`
    /// Too high: a body turns by more than a radian per substep and its contacts (refreshed
    /// once per step) lag its faces. Too low: spinning bodies are slowed.
    pub max_angular_speed: f32,
    /// Coarsest spacing of `f32` positions the engine's accuracy holds with, metres. Moving
    /// bodies farther from the origin than [`PhysicsSettings::precise_range`] (where the
    /// spacing is coarser) are named once in `StepOutput::far_bodies`.
    /// Default: `0.001` (range 16,384 m)
    /// Too high: bodies lose slow motions to rounding (at 1e6 m the spacing is 6 cm) without
    /// a word. Too low: warnings for worlds that are fine.
    pub max_position_spacing: f32,
    /// Whether resting islands fall asleep.
    /// Default: `true`
    pub sleep_enabled: bool,
    /// Linear speed below which a body counts as resting, m/s.
    /// Default: `0.05`
    /// Too high: slowly moving bodies freeze. Too low: islands never sleep (CPU cost).
    pub sleep_linear_threshold: f32,
    /// Angular speed below which a body counts as resting, rad/s.
    /// Default: `0.1`
    /// Too high: slow spins freeze. Too low: islands never sleep.
    pub sleep_angular_threshold: f32,
    /// Time an island must rest before it sleeps, seconds.
    /// Default: `0.5`
    /// Too high: CPU wasted on resting bodies. Too low: bodies freeze at the top of an arc.
    pub time_to_sleep: f32,
    /// Global switch for continuous collision detection (bodies also opt in).
    /// Default: `true`
    pub ccd_enabled: bool,
    /// Joint stiffness, Hz: how fast the biased passes pull a joint's position error back
    /// (clamped to a quarter of the substep rate, see `JOINT_STIFFNESS_MAX_SUBSTEP_FRACTION`;
    /// a joint carrying more than its own weight stiffens toward that clamp).
    /// Default: `60` (Box2D v3's: twice its contact stiffness)
    /// Too high: no better than rigid at the clamp. Too low: joints stretch and sag visibly
    /// under load (chains, heavy ends).
    pub joint_hertz: f32,
    /// Joint damping ratio (dimensionless).
    /// Default: `2`
    /// Too high: the position error is pulled back sluggishly. Too low: joints ring after a
    /// jolt.
    pub joint_damping_ratio: f32,
    /// A contact normal with `y` at least this (toward the body) marks the body grounded.
    /// Default: `0.7`
    /// Too high: slopes do not count as ground. Too low: walls count as ground.
    pub grounded_min_normal_y: f32,
}

impl PhysicsSettings {
    /// Checks every field against the values the engine can simulate: finite numbers,
    /// positive where a rate, length or count must be, fractions in their range.
    ///
    /// # Errors
    /// [`SettingsError::OutOfRange`] naming the first field that is not.
    pub fn validate(&self) -> Result<(), SettingsError> {
        fn check(
            field: &'static str,
            value: f32,
            ok: bool,
            expected: &'static str,
        ) -> Result<(), SettingsError> {
            if value.is_finite() && ok {
                Ok(())
            } else {
                Err(SettingsError::OutOfRange {
                    field,
                    value: f64::from(value),
                    expected,
                })
            }
        }
        let count = |field: &'static str, n: u32, min: u32| {
            if n >= min {
                Ok(())
            } else {
                Err(SettingsError::OutOfRange {
                    field,
                    value: f64::from(n),
                    expected: if min == 0 { ">= 0" } else { ">= 1" },
                })
            }
        };
        let positive = |field, v: f32| check(field, v, v > 0.0, "finite and > 0");
        let non_negative = |field, v: f32| check(field, v, v >= 0.0, "finite and >= 0");
        positive("dt", self.dt)?;
        for (field, g) in [
            ("gravity.x", self.gravity.x),
            ("gravity.y", self.gravity.y),
            ("gravity.z", self.gravity.z),
        ] {
            check(field, g, true, "finite")?;
        }
        count("substeps", self.substeps, 1)?;
        count("solver_iterations", self.solver_iterations, 1)?;
        count("relax_iterations", self.relax_iterations, 0)?;
        positive("contact_hertz", self.contact_hertz)?;
        non_negative("contact_damping_ratio", self.contact_damping_ratio)?;
        positive("max_contact_push_speed", self.max_contact_push_speed)?;
        check(
            "max_penetration_fraction",
            self.max_penetration_fraction,
            self.max_penetration_fraction > 0.0 && self.max_penetration_fraction < 1.0,
            "in (0, 1)",
        )?;
        non_negative("max_support_mass_ratio", self.max_support_mass_ratio)?;
        positive("linear_slop", self.linear_slop)?;
        non_negative("speculative_distance", self.speculative_distance)?;
        non_negative("max_speculative_distance", self.max_speculative_distance)?;
        non_negative("aabb_margin", self.aabb_margin)?;
        non_negative("restitution_threshold", self.restitution_threshold)?;
        non_negative("static_friction_speed", self.static_friction_speed)?;
        positive("max_linear_speed", self.max_linear_speed)?;
        positive("max_angular_speed", self.max_angular_speed)?;
        positive("max_position_spacing", self.max_position_spacing)?;
        non_negative("sleep_linear_threshold", self.sleep_linear_threshold)?;
        non_negative("sleep_angular_threshold", self.sleep_angular_threshold)?;
        non_negative("time_to_sleep", self.time_to_sleep)?;
        positive("joint_hertz", self.joint_hertz)?;
        non_negative("joint_damping_ratio", self.joint_damping_ratio)?;
        check(
            "grounded_min_normal_y",
            self.grounded_min_normal_y,
            (-1.0..=1.0).contains(&self.grounded_min_normal_y),
            "in [-1, 1]",
        )?;
        Ok(())
    }

    /// Distance from the origin, metres, within which `f32` positions are spaced at most
    /// [`PhysicsSettings::max_position_spacing`] apart: `2^(⌊log₂ spacing⌋ + 24)` (16,384 m
    /// for 1 mm).
    #[must_use]
    pub fn precise_range(&self) -> f32 {
        range_of_spacing(self.max_position_spacing)
    }

    /// [`PhysicsSettings::precise_range`] for a body whose smallest dimension is `size`
    /// metres: where positions are also spaced at most `max_penetration_fraction` of it
    /// apart, the resting accuracy the contacts hold it to (256 m for a 1 mm body at 2 %;
    /// 1,000 m up, `f32` spaces its positions 6 % of it apart).
    #[must_use]
    pub fn precise_range_for(&self, size: f32) -> f32 {
        range_of_spacing(self.position_spacing_for(size))
    }

    /// The coarsest spacing of `f32` positions that holds a body whose smallest dimension
    /// is `size` metres: `max_position_spacing`, or `max_penetration_fraction` of `size`
    /// where that is finer.
    pub(crate) fn position_spacing_for(&self, size: f32) -> f32 {
        let own = self.max_penetration_fraction * size;
        if own > 0.0 && own < self.max_position_spacing {
            own
        } else {
            self.max_position_spacing
        }
    }
}

/// Distance from the origin within which `f32` positions are spaced at most `spacing`
/// apart: `2^(⌊log₂ spacing⌋ + 24)`.
fn range_of_spacing(spacing: f32) -> f32 {
    if spacing.is_nan() || spacing <= 0.0 {
        return f32::MAX;
    }
    let e = spacing.log2().floor() + 24.0;
    if e >= 128.0 {
        f32::MAX
    } else {
        e.exp2()
    }
}

impl Default for PhysicsSettings {
    fn default() -> Self {
        Self {
            dt: 1.0 / 60.0,
            gravity: Vec3::new(0.0, -9.81, 0.0),
            substeps: 4,
            solver_iterations: 1,
            relax_iterations: 1,
            contact_hertz: 32.0,
            contact_damping_ratio: 5.0,
            max_contact_push_speed: 3.0,
            max_penetration_fraction: 0.02,
            max_support_mass_ratio: 3.0,
            linear_slop: 0.001,
            speculative_distance: 0.02,
            max_speculative_distance: 0.5,
            aabb_margin: 0.1,
            restitution_threshold: 0.1,
            static_friction_speed: 0.05,
            max_linear_speed: 1000.0,
            max_angular_speed: 200.0,
            max_position_spacing: 0.001,
            sleep_enabled: true,
            sleep_linear_threshold: 0.05,
            sleep_angular_threshold: 0.1,
            time_to_sleep: 0.5,
            ccd_enabled: true,
            joint_hertz: 60.0,
            joint_damping_ratio: 2.0,
            grounded_min_normal_y: 0.7,
        }
    }
}
