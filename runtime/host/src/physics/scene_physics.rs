//! [`ScenePhysics`]: the physics settings a scene file asks for (a preset plus overrides).

use onyx_physics::{PhysicsPreset, PhysicsSettings};
use serde::{Deserialize, Serialize};

/// How a scene wants to be simulated: a named accuracy preset, optionally adjusted.
///
/// ```ron
/// physics: (preset: Precise, gravity: Some((0.0, -1.62, 0.0))),
/// ```
///
/// Loading the scene sets the host's fixed step rate (which is the physics step rate) and
/// the physics settings; see `docs/physics-accuracy.md` for what each preset costs and how
/// wrong it is.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScenePhysics {
    /// The accuracy profile (`Fast`, `Balanced`, `Precise`).
    #[serde(default)]
    pub preset: PhysicsPreset,
    /// Fixed steps per second, instead of the preset's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fixed_hz: Option<f64>,
    /// Substeps per step, instead of the preset's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub substeps: Option<u32>,
    /// Gravity, m/s², instead of `(0, -9.81, 0)`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gravity: Option<[f32; 3]>,
}

/// Highest fixed step rate a scene may ask for.
pub const MAX_SCENE_FIXED_HZ: f64 = 2000.0;
/// Most substeps a scene may ask for.
pub const MAX_SCENE_SUBSTEPS: u32 = 64;

impl ScenePhysics {
    /// These settings with a preset and nothing overridden.
    #[must_use]
    pub fn preset(preset: PhysicsPreset) -> Self {
        Self {
            preset,
            ..Self::default()
        }
    }

    /// Checks the overrides; the message names the bad value.
    ///
    /// # Errors
    /// A rate that is not finite or outside (0, [`MAX_SCENE_FIXED_HZ`]], substeps outside
    /// 1..=[`MAX_SCENE_SUBSTEPS`], or a non-finite gravity.
    pub fn validate(&self) -> Result<(), String> {
        if let Some(hz) = self.fixed_hz {
            if !(hz.is_finite() && hz > 0.0 && hz <= MAX_SCENE_FIXED_HZ) {
                return Err(format!(
                    "physics.fixed_hz must be in (0, {MAX_SCENE_FIXED_HZ}], got {hz}"
                ));
            }
        }
        if let Some(n) = self.substeps {
            if !(1..=MAX_SCENE_SUBSTEPS).contains(&n) {
                return Err(format!(
                    "physics.substeps must be in 1..={MAX_SCENE_SUBSTEPS}, got {n}"
                ));
            }
        }
        if let Some(g) = self.gravity {
            if !g.iter().all(|c| c.is_finite()) {
                return Err(format!("physics.gravity must be finite, got {g:?}"));
            }
        }
        Ok(())
    }

    /// Fixed steps per second.
    #[must_use]
    pub fn fixed_hz(&self) -> f64 {
        self.fixed_hz
            .unwrap_or_else(|| f64::from(self.preset.step_hz()))
    }

    /// The physics settings (the step length follows [`ScenePhysics::fixed_hz`]).
    #[must_use]
    pub fn settings(&self) -> PhysicsSettings {
        let mut s = self.preset.settings();
        s.dt = (1.0 / self.fixed_hz()) as f32;
        if let Some(n) = self.substeps {
            s.substeps = n;
        }
        if let Some(g) = self.gravity {
            s.gravity = g.into();
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overrides_apply_on_top_of_the_preset() {
        let p = ScenePhysics {
            preset: PhysicsPreset::Fast,
            fixed_hz: Some(50.0),
            substeps: Some(3),
            gravity: Some([0.0, -1.62, 0.0]),
        };
        assert!(p.validate().is_ok());
        let s = p.settings();
        assert!((s.dt - 0.02).abs() < 1e-7);
        assert_eq!(s.substeps, 3);
        assert_eq!(s.gravity.y, -1.62);
        assert_eq!(
            s.contact_hertz,
            PhysicsPreset::Fast.settings().contact_hertz
        );
    }

    #[test]
    fn bad_overrides_are_named() {
        let bad = [
            ScenePhysics {
                fixed_hz: Some(f64::NAN),
                ..ScenePhysics::default()
            },
            ScenePhysics {
                fixed_hz: Some(0.0),
                ..ScenePhysics::default()
            },
            ScenePhysics {
                substeps: Some(0),
                ..ScenePhysics::default()
            },
            ScenePhysics {
                gravity: Some([0.0, f32::INFINITY, 0.0]),
                ..ScenePhysics::default()
            },
        ];
        for b in bad {
            let message = b.validate().expect_err("must be refused");
            assert!(message.starts_with("physics."), "{message}");
        }
    }
}
