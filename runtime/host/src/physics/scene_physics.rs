//! [`ScenePhysics`]: the physics settings a scene file asks for (a preset plus overrides).

use onyx_physics::glam::Vec3;
use onyx_physics::{PhysicsPreset, PhysicsSettings};
use serde::{Deserialize, Serialize};

/// Highest fixed step rate a scene may ask for.
pub const MAX_SCENE_FIXED_HZ: f64 = 2000.0;
/// Most substeps a scene may ask for.
pub const MAX_SCENE_SUBSTEPS: u32 = 64;
/// Most solver or relax passes per substep a scene may ask for.
pub const MAX_SCENE_ITERATIONS: u32 = 64;

/// A scene-file value of a [`PhysicsSettings`] field, as the engine takes it.
trait SettingValue: Copy {
    type Engine;
    fn engine(self) -> Self::Engine;
    fn from_engine(value: Self::Engine) -> Self;
}

macro_rules! same_value {
    ($($ty:ty),*) => {$(
        impl SettingValue for $ty {
            type Engine = $ty;
            fn engine(self) -> $ty {
                self
            }
            fn from_engine(value: $ty) -> $ty {
                value
            }
        }
    )*};
}
same_value!(f32, u32, bool);

/// Vectors are written as tuples, `(0.0, -1.62, 0.0)`.
impl SettingValue for [f32; 3] {
    type Engine = Vec3;
    fn engine(self) -> Vec3 {
        Vec3::from(self)
    }
    fn from_engine(value: Vec3) -> [f32; 3] {
        value.to_array()
    }
}

/// Declares [`ScenePhysics`] with one optional override per [`PhysicsSettings`] field (the
/// step length `dt` is the scene's `fixed_hz`), and what iterates them. The one list of
/// the fields a scene can set.
macro_rules! scene_physics {
    ($($(#[doc = $doc:literal])* $field:ident: $ty:ty,)*) => {
        /// How a scene wants to be simulated: a named accuracy preset, and any
        /// [`PhysicsSettings`] field set explicitly (each under its own name; the step length
        /// is `fixed_hz`). The settings are built in this order: the defaults, the preset
        /// ([`PhysicsPreset::apply`]: step rate and substeps), the fields the scene names.
        ///
        /// ```ron
        /// physics: (preset: Precise, gravity: Some((0.0, -1.62, 0.0)), restitution_threshold: Some(0.0)),
        /// ```
        ///
        /// Loading the scene sets the host's fixed step rate (which is the physics step rate)
        /// and the physics settings; see `docs/physics-accuracy.md` for what each preset costs
        /// and how wrong it is, and `PhysicsSettings` for what each field does.
        #[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
        #[serde(deny_unknown_fields)]
        pub struct ScenePhysics {
            /// The accuracy profile (`Fast`, `Balanced`, `Precise`).
            #[serde(default)]
            pub preset: PhysicsPreset,
            /// Fixed steps per second (the physics step length is its inverse), instead of
            /// the preset's.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub fixed_hz: Option<f64>,
            $(
                $(#[doc = $doc])*
                #[serde(default, skip_serializing_if = "Option::is_none")]
                pub $field: Option<$ty>,
            )*
        }

        /// Every field a scene can set besides the preset, as written in scene files.
        pub const SCENE_PHYSICS_FIELDS: &[&str] = &["fixed_hz", $(stringify!($field)),*];

        impl ScenePhysics {
            /// `settings` with every field this scene names set.
            fn overridden(&self, mut settings: PhysicsSettings) -> PhysicsSettings {
                if let Some(hz) = self.fixed_hz {
                    settings.dt = (1.0 / hz) as f32;
                }
                $(
                    if let Some(value) = self.$field {
                        settings.$field = SettingValue::engine(value);
                    }
                )*
                settings
            }

            /// A scene that names every field, with the values of `settings` (`fixed_hz`
            /// from its `dt`).
            #[must_use]
            pub fn explicit(preset: PhysicsPreset, settings: &PhysicsSettings) -> Self {
                Self {
                    preset,
                    fixed_hz: Some(1.0 / f64::from(settings.dt)),
                    $($field: Some(SettingValue::from_engine(settings.$field)),)*
                }
            }
        }
    };
}

scene_physics! {
    /// Gravity, m/s² (`PhysicsSettings::gravity`).
    gravity: [f32; 3],
    /// Substeps per step, instead of the preset's (`PhysicsSettings::substeps`).
    substeps: u32,
    /// Biased solver passes per substep (`PhysicsSettings::solver_iterations`).
    solver_iterations: u32,
    /// Relax passes per substep (`PhysicsSettings::relax_iterations`).
    relax_iterations: u32,
    /// Contact stiffness, Hz (`PhysicsSettings::contact_hertz`).
    contact_hertz: f32,
    /// Contact damping ratio (`PhysicsSettings::contact_damping_ratio`).
    contact_damping_ratio: f32,
    /// Fastest push-out of overlap, m/s (`PhysicsSettings::max_contact_push_speed`).
    max_contact_push_speed: f32,
    /// Penetration budget as a fraction of a body's size
    /// (`PhysicsSettings::max_penetration_fraction`).
    max_penetration_fraction: f32,
    /// Largest mass ratio a resting contact is solved with
    /// (`PhysicsSettings::max_support_mass_ratio`).
    max_support_mass_ratio: f32,
    /// Contact distance tolerance, m (`PhysicsSettings::linear_slop`).
    linear_slop: f32,
    /// Speculative contact distance, m (`PhysicsSettings::speculative_distance`).
    speculative_distance: f32,
    /// Cap on the speed-dependent speculative distance, m
    /// (`PhysicsSettings::max_speculative_distance`).
    max_speculative_distance: f32,
    /// Broadphase box enlargement, m (`PhysicsSettings::aabb_margin`).
    aabb_margin: f32,
    /// Impact speed at or below which contacts do not bounce, m/s
    /// (`PhysicsSettings::restitution_threshold`).
    restitution_threshold: f32,
    /// Tangential speed below which static friction applies, m/s
    /// (`PhysicsSettings::static_friction_speed`).
    static_friction_speed: f32,
    /// Linear speed cap, m/s (`PhysicsSettings::max_linear_speed`).
    max_linear_speed: f32,
    /// Spin cap, rad/s (`PhysicsSettings::max_angular_speed`).
    max_angular_speed: f32,
    /// Coarsest f32 position spacing the accuracy holds with, m
    /// (`PhysicsSettings::max_position_spacing`).
    max_position_spacing: f32,
    /// Whether resting islands fall asleep (`PhysicsSettings::sleep_enabled`).
    sleep_enabled: bool,
    /// Linear speed below which a body rests, m/s (`PhysicsSettings::sleep_linear_threshold`).
    sleep_linear_threshold: f32,
    /// Angular speed below which a body rests, rad/s
    /// (`PhysicsSettings::sleep_angular_threshold`).
    sleep_angular_threshold: f32,
    /// Time an island must rest before it sleeps, s (`PhysicsSettings::time_to_sleep`).
    time_to_sleep: f32,
    /// Global switch for continuous collision detection (`PhysicsSettings::ccd_enabled`).
    ccd_enabled: bool,
    /// Joint stiffness, Hz (`PhysicsSettings::joint_hertz`).
    joint_hertz: f32,
    /// Joint damping ratio (`PhysicsSettings::joint_damping_ratio`).
    joint_damping_ratio: f32,
    /// Contact normal `y` from which a body counts as grounded
    /// (`PhysicsSettings::grounded_min_normal_y`).
    grounded_min_normal_y: f32,
}

impl ScenePhysics {
    /// These settings with a preset and nothing overridden.
    #[must_use]
    pub fn preset(preset: PhysicsPreset) -> Self {
        Self {
            preset,
            ..Self::default()
        }
    }

    /// This scene simulated with `preset` instead (a preset chosen on the command line): the
    /// preset's step rate and substeps replace the scene's, every other field the scene
    /// names is kept. Its settings are `preset.apply(self.settings())`.
    #[must_use]
    pub fn with_preset(&self, preset: PhysicsPreset) -> Self {
        Self {
            preset,
            fixed_hz: None,
            substeps: None,
            ..self.clone()
        }
    }

    /// Checks the scene's limits and the settings it makes; the message names the field and
    /// the value (`physics.substeps must be in 1..=64, got 0`).
    ///
    /// # Errors
    /// A rate that is not finite or outside (0, [`MAX_SCENE_FIXED_HZ`]], substeps outside
    /// 1..=[`MAX_SCENE_SUBSTEPS`], solver or relax passes past [`MAX_SCENE_ITERATIONS`], or
    /// any field [`PhysicsSettings::validate`] refuses (NaN, infinity, out of range).
    pub fn validate(&self) -> Result<(), String> {
        if let Some(hz) = self.fixed_hz {
            if !(hz.is_finite() && hz > 0.0 && hz <= MAX_SCENE_FIXED_HZ) {
                return Err(format!(
                    "physics.fixed_hz must be in (0, {MAX_SCENE_FIXED_HZ}], got {hz}"
                ));
            }
        }
        let counts = [
            ("substeps", self.substeps, 1, MAX_SCENE_SUBSTEPS),
            (
                "solver_iterations",
                self.solver_iterations,
                1,
                MAX_SCENE_ITERATIONS,
            ),
            (
                "relax_iterations",
                self.relax_iterations,
                0,
                MAX_SCENE_ITERATIONS,
            ),
        ];
        for (field, value, min, max) in counts {
            if let Some(n) = value {
                if !(min..=max).contains(&n) {
                    return Err(format!("physics.{field} must be in {min}..={max}, got {n}"));
                }
            }
        }
        self.settings().validate().map_err(|e| e.to_string())
    }

    /// Fixed steps per second.
    #[must_use]
    pub fn fixed_hz(&self) -> f64 {
        self.fixed_hz
            .unwrap_or_else(|| f64::from(self.preset.step_hz()))
    }

    /// The physics settings: the defaults, the preset applied, then every field the scene
    /// names (the step length follows [`ScenePhysics::fixed_hz`]).
    #[must_use]
    pub fn settings(&self) -> PhysicsSettings {
        self.overridden(self.preset.settings())
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
            ..ScenePhysics::default()
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

    /// Every settings field a scene names reaches the engine, and only those.
    #[test]
    fn every_field_of_the_settings_is_settable_and_round_trips() {
        // Values that differ from the defaults in every field.
        let odd = PhysicsSettings {
            dt: 1.0 / 90.0,
            gravity: Vec3::new(0.5, -1.62, 0.25),
            substeps: 7,
            solver_iterations: 3,
            relax_iterations: 2,
            contact_hertz: 21.0,
            contact_damping_ratio: 3.5,
            max_contact_push_speed: 1.5,
            max_penetration_fraction: 0.04,
            max_support_mass_ratio: 20.0,
            linear_slop: 0.002,
            speculative_distance: 0.03,
            max_speculative_distance: 0.75,
            aabb_margin: 0.05,
            restitution_threshold: 0.0,
            static_friction_speed: 0.02,
            max_linear_speed: 5000.0,
            max_angular_speed: 400.0,
            max_position_spacing: 0.0078,
            sleep_enabled: false,
            sleep_linear_threshold: 0.01,
            sleep_angular_threshold: 0.02,
            time_to_sleep: 2.0,
            ccd_enabled: false,
            joint_hertz: 45.0,
            joint_damping_ratio: 1.5,
            grounded_min_normal_y: 0.5,
        };
        let scene = ScenePhysics::explicit(PhysicsPreset::Fast, &odd);
        scene.validate().unwrap();
        let got = scene.settings();
        assert!(
            (got.dt - odd.dt).abs() < 1e-9,
            "dt {} vs {}",
            got.dt,
            odd.dt
        );
        assert_eq!(PhysicsSettings { dt: odd.dt, ..got }, odd);
        // Through the file form and back.
        let text = ron::to_string(&scene).unwrap();
        let read: ScenePhysics = ron::from_str(&text).unwrap();
        assert_eq!(read, scene);
        // 27 settings fields: `dt` is written as `fixed_hz`.
        assert_eq!(SCENE_PHYSICS_FIELDS.len(), 27);
        for field in SCENE_PHYSICS_FIELDS {
            assert!(text.contains(&format!("{field}:")), "{field} not in {text}");
        }
    }

    #[test]
    fn a_command_line_preset_keeps_what_it_does_not_name() {
        let moon = ScenePhysics {
            preset: PhysicsPreset::Fast,
            fixed_hz: Some(45.0),
            substeps: Some(6),
            gravity: Some([0.0, -1.62, 0.0]),
            restitution_threshold: Some(0.0),
            max_linear_speed: Some(3000.0),
            ..ScenePhysics::default()
        };
        for preset in PhysicsPreset::ALL {
            let chosen = moon.with_preset(preset);
            assert_eq!(chosen.settings(), preset.apply(moon.settings()));
            assert_eq!(chosen.fixed_hz(), f64::from(preset.step_hz()));
            assert_eq!(chosen.settings().gravity.y, -1.62);
        }
    }

    #[test]
    fn bad_overrides_are_named() {
        let bad = [
            (
                ScenePhysics {
                    fixed_hz: Some(f64::NAN),
                    ..ScenePhysics::default()
                },
                "physics.fixed_hz",
            ),
            (
                ScenePhysics {
                    fixed_hz: Some(0.0),
                    ..ScenePhysics::default()
                },
                "physics.fixed_hz",
            ),
            (
                ScenePhysics {
                    substeps: Some(0),
                    ..ScenePhysics::default()
                },
                "physics.substeps",
            ),
            (
                ScenePhysics {
                    relax_iterations: Some(1000),
                    ..ScenePhysics::default()
                },
                "physics.relax_iterations",
            ),
            (
                ScenePhysics {
                    gravity: Some([0.0, f32::INFINITY, 0.0]),
                    ..ScenePhysics::default()
                },
                "physics.gravity.y",
            ),
            (
                ScenePhysics {
                    contact_hertz: Some(f32::NAN),
                    ..ScenePhysics::default()
                },
                "physics.contact_hertz",
            ),
            (
                ScenePhysics {
                    max_penetration_fraction: Some(1.5),
                    ..ScenePhysics::default()
                },
                "physics.max_penetration_fraction",
            ),
            (
                ScenePhysics {
                    max_linear_speed: Some(-1.0),
                    ..ScenePhysics::default()
                },
                "physics.max_linear_speed",
            ),
        ];
        for (b, field) in bad {
            let message = b.validate().expect_err("must be refused");
            assert!(message.starts_with(field), "{message}");
        }
    }
}
