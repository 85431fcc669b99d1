//! The scenes: one file each, all behind [`Scene`]. A scene builds itself into any
//! [`Engine`], says how many steps to run, and measures an error figure through a [`Trial`].
//!
//! To add a scene: write `src/scenes/NAME.rs` with a unit struct implementing [`Scene`], and
//! list it in [`all`].

use onyx_physics::glam::Vec3;

use crate::engine::{BodyId, Engine, StepSettings};
use crate::joint_spec::JointSpec;

pub mod big_pyramid;
pub mod bounce;
pub mod bridge;
pub mod chain;
pub mod degenerate_hulls;
pub mod elastic_crowd;
pub mod far_origin;
pub mod free_fall;
pub mod frictionless_random;
pub mod frictionless_stacks;
pub mod hinge_motor;
pub mod incline;
pub mod long_run;
pub mod mass_ratio;
pub mod mass_ratio_ladder;
pub mod pendulum;
pub mod poured_spheres;
pub mod prismatic_limit;
pub mod pyramid;
pub mod ragdolls;
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
        &elastic_crowd::ElasticCrowd,
        &mass_ratio_ladder::MassRatioLadder,
        &size_ladder::SizeLadder,
        &frictionless_stacks::FrictionlessStacks,
        &frictionless_random::PLACED,
        &frictionless_random::DROPPED,
        &pendulum::Pendulum,
        &chain::Chain,
        &hinge_motor::HingeMotor,
        &prismatic_limit::PrismaticLimit,
        &bridge::Bridge,
        &ragdolls::Ragdolls,
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

/// A point given in a body's frame (or in world space for the world, `None`), in world space
/// at the body's current pose.
#[must_use]
pub fn anchor_world(e: &dyn Engine, body: Option<BodyId>, local: Vec3) -> Vec3 {
    match body {
        Some(id) => e.position(id) + e.rotation(id) * local,
        None => local,
    }
}

/// How far apart a joint's two anchors are, m (0 for a joint that holds exactly).
#[must_use]
pub fn joint_gap(e: &dyn Engine, j: &JointSpec) -> f32 {
    anchor_world(e, j.a, j.anchor_a).distance(anchor_world(e, Some(j.b), j.anchor_b))
}

/// Adds every joint of `joints` to `e` and hands them back.
pub fn add_joints(e: &mut dyn Engine, joints: Vec<JointSpec>) -> Vec<JointSpec> {
    for j in &joints {
        e.add_joint(j);
    }
    joints
}

/// The largest of `values`, NaN if any is NaN (a body that blew up), 0 when empty.
#[must_use]
pub fn max_or_nan(values: impl IntoIterator<Item = f64>) -> f64 {
    values.into_iter().fold(0.0, |w: f64, x| {
        if w.is_nan() || x.is_nan() {
            f64::NAN
        } else {
            w.max(x)
        }
    })
}
