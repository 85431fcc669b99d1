//! The scenes: one file each, all behind [`Scene`]. A scene builds itself into any
//! [`Engine`], says how many steps to run, and measures an error figure through a [`Trial`].
//!
//! To add a scene: write `src/scenes/NAME.rs` with a unit struct implementing [`Scene`], and
//! list it in [`all`].

use onyx_physics::glam::Vec3;

use crate::engine::{BodyId, Engine, StepSettings};

pub mod big_pyramid;
pub mod bounce;
pub mod degenerate_hulls;
pub mod far_origin;
pub mod free_fall;
pub mod frictionless_stacks;
pub mod incline;
pub mod long_run;
pub mod mass_ratio;
pub mod mass_ratio_ladder;
pub mod poured_spheres;
pub mod pyramid;
pub mod restitution_ladder;
pub mod rolling;
pub mod rotation_energy;
pub mod size_ladder;
pub mod sliding;
pub mod stack;
pub mod tiny_huge;
pub mod tunneling;
pub mod wide_wall_ccd;

/// Problem size: `Quick` for the smoke path, `Full` for the real comparison.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Size {
    /// Reduced sizes and step counts.
    Quick,
    /// Sizes stated by each scene.
    Full,
}

/// What a scene's figure is compared against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reference {
    /// The trial's figure already is the error against an analytic answer (or the ideal
    /// zero of a drift/penetration/leak figure).
    Analytic,
    /// The figure is a quantity; its error is the distance to the same quantity from the same
    /// engine at the converged setting [`StepSettings::REFERENCE`].
    Converged,
}

/// One scene, engine-neutral.
pub trait Scene: Sync {
    /// Short identifier used by `--scenes`.
    fn name(&self) -> &'static str;
    /// What it measures, with the unit of the error figure.
    fn metric(&self) -> &'static str;
    /// What the figure is compared against.
    fn reference(&self) -> Reference {
        Reference::Analytic
    }
    /// Steps to run at this setting.
    fn steps(&self, s: StepSettings, size: Size) -> usize;
    /// Builds the scene into `e`; the returned trial measures it.
    fn build(&self, e: &mut dyn Engine, s: StepSettings, size: Size) -> Box<dyn Trial>;
}

/// A built scene: observes each step and produces the figure at the end.
pub trait Trial {
    /// Called after every step.
    fn observe(&mut self, _e: &dyn Engine) {}
    /// The figure (see [`Scene::reference`]); NaN if the simulation blew up.
    fn figure(&self, e: &dyn Engine) -> f64;
    /// What else the run showed, for the summary (e.g. GJK/EPA iterations); none by default.
    fn detail(&self, _e: &dyn Engine) -> Option<String> {
        None
    }
}

/// Every scene, in report order (most valuable first).
#[must_use]
pub fn all() -> Vec<&'static dyn Scene> {
    vec![
        &free_fall::FreeFall,
        &bounce::BounceLadder,
        &sliding::Sliding,
        &stack::Stack,
        &pyramid::Pyramid,
        &tunneling::Tunneling,
        &far_origin::FarOrigin,
        &mass_ratio::MassRatio,
        &incline::Incline,
        &rolling::Rolling,
        &long_run::LongRun,
        &tiny_huge::TinyHuge,
        &big_pyramid::BigPyramid,
        &poured_spheres::PouredSpheres,
        &degenerate_hulls::DegenerateHulls,
        &rotation_energy::RotationEnergy,
        &wide_wall_ccd::WideWallCcd,
        &restitution_ladder::RestitutionLadder,
        &mass_ratio_ladder::MassRatioLadder,
        &size_ladder::SizeLadder,
        &frictionless_stacks::FrictionlessStacks,
    ]
}

/// Steps for `seconds` of simulated time at this setting.
#[must_use]
pub fn steps_for(seconds: f32, s: StepSettings) -> usize {
    (seconds * s.hz).round().max(1.0) as usize
}

/// Largest displacement of `ids` from their recorded start positions (NaN if any is not
/// finite).
#[must_use]
pub fn max_displacement(e: &dyn Engine, ids: &[(BodyId, Vec3)]) -> f64 {
    let mut worst = 0.0f64;
    for &(id, p0) in ids {
        let p = e.position(id);
        if !p.is_finite() {
            return f64::NAN;
        }
        worst = worst.max(f64::from((p - p0).length()));
    }
    worst
}
