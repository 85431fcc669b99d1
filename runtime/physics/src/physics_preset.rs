//! [`PhysicsPreset`]: named accuracy profiles (fast / balanced / precise), chosen from the
//! measurements of `bench/physics-compare` (see `docs/physics-accuracy.md`).

use std::fmt;
use std::str::FromStr;

use crate::PhysicsSettings;

/// A named trade between speed and accuracy. Each preset is one point of the benchmark's
/// sweep (step rate × substeps, everything else at its default), so its measured error and
/// cost are the benchmark's figures for that point, listed in `docs/physics-accuracy.md`.
///
/// ```
/// use onyx_physics::{PhysicsPreset, PhysicsWorld};
///
/// let world = PhysicsWorld::new(PhysicsPreset::Precise.settings());
/// assert_eq!(world.settings().substeps, 4);
/// assert_eq!(world.settings().dt, 1.0 / 120.0);
/// assert_eq!("fast".parse::<PhysicsPreset>(), Ok(PhysicsPreset::Fast));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum PhysicsPreset {
    /// 30 Hz × 2 substeps: crowds, debris, background props. Trajectories and resting
    /// contacts are a few millimetres off; tall stacks sink visibly; thin walls need CCD.
    Fast,
    /// 60 Hz × 4 substeps (the default settings): games and interactive scenes. Stacks and
    /// pyramids hold; bounces and friction within a few per cent.
    #[default]
    Balanced,
    /// 120 Hz × 4 substeps: engineering-style scenes, tall stacks, heavy-on-light loads,
    /// small bodies. About twice the cost of balanced per simulated second. (120 × 8 costs
    /// twice as much again and is no more accurate on the benchmark's scenes.)
    Precise,
}

impl PhysicsPreset {
    /// Every preset, cheapest first.
    pub const ALL: [PhysicsPreset; 3] = [
        PhysicsPreset::Fast,
        PhysicsPreset::Balanced,
        PhysicsPreset::Precise,
    ];

    /// Lower-case name, as written in scene files and on the command line.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            PhysicsPreset::Fast => "fast",
            PhysicsPreset::Balanced => "balanced",
            PhysicsPreset::Precise => "precise",
        }
    }

    /// Fixed steps per second this preset is measured at.
    #[must_use]
    pub fn step_hz(self) -> f32 {
        match self {
            PhysicsPreset::Fast => 30.0,
            PhysicsPreset::Balanced => 60.0,
            PhysicsPreset::Precise => 120.0,
        }
    }

    /// Substeps per step.
    #[must_use]
    pub fn substeps(self) -> u32 {
        match self {
            PhysicsPreset::Fast => 2,
            PhysicsPreset::Balanced => 4,
            PhysicsPreset::Precise => 4,
        }
    }

    /// The full settings: the defaults with this preset's step length and substeps.
    #[must_use]
    pub fn settings(self) -> PhysicsSettings {
        self.apply(PhysicsSettings::default())
    }

    /// `settings` with what this preset names (step length and substeps) and nothing else
    /// changed: a preset chosen on a command line over a scene's own settings keeps the
    /// scene's gravity, thresholds and caps.
    #[must_use]
    pub fn apply(self, settings: PhysicsSettings) -> PhysicsSettings {
        PhysicsSettings {
            dt: 1.0 / self.step_hz(),
            substeps: self.substeps(),
            ..settings
        }
    }
}

impl fmt::Display for PhysicsPreset {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A preset name that is not one of `fast`, `balanced`, `precise`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownPreset(pub String);

impl fmt::Display for UnknownPreset {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "unknown physics preset {:?} (expected fast, balanced or precise)",
            self.0
        )
    }
}

impl std::error::Error for UnknownPreset {}

impl FromStr for PhysicsPreset {
    type Err = UnknownPreset;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        PhysicsPreset::ALL
            .into_iter()
            .find(|p| p.name().eq_ignore_ascii_case(s.trim()))
            .ok_or_else(|| UnknownPreset(s.to_string()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn balanced_is_the_default_settings() {
        assert_eq!(
            PhysicsPreset::Balanced.settings(),
            PhysicsSettings::default()
        );
        assert_eq!(PhysicsPreset::default(), PhysicsPreset::Balanced);
    }

    #[test]
    fn a_preset_over_a_scene_keeps_what_it_does_not_name() {
        let moon = PhysicsSettings {
            gravity: glam::Vec3::new(0.0, -1.62, 0.0),
            restitution_threshold: 0.0,
            max_linear_speed: 5000.0,
            ..PhysicsSettings::default()
        };
        let s = PhysicsPreset::Precise.apply(moon);
        assert_eq!(s.gravity, moon.gravity);
        assert_eq!(s.restitution_threshold, 0.0);
        assert_eq!(s.max_linear_speed, 5000.0);
        assert_eq!((s.dt, s.substeps), (1.0 / 120.0, 4));
    }

    #[test]
    fn presets_get_dearer_in_order() {
        let work = |p: PhysicsPreset| p.step_hz() * p.substeps() as f32;
        assert!(work(PhysicsPreset::Fast) < work(PhysicsPreset::Balanced));
        assert!(work(PhysicsPreset::Balanced) < work(PhysicsPreset::Precise));
    }

    #[test]
    fn names_round_trip() {
        for p in PhysicsPreset::ALL {
            assert_eq!(p.name().parse::<PhysicsPreset>(), Ok(p));
            assert_eq!(p.to_string(), p.name());
        }
        assert!("turbo".parse::<PhysicsPreset>().is_err());
    }
}
