//! The documented defaults of `PhysicsSettings` ("Default: `…`" doc lines) equal `Default`.
use onyx_physics::PhysicsSettings;

fn parse_num(s: &str) -> f32 {
    if let Some((a, b)) = s.split_once('/') {
        return a.trim().parse::<f32>().unwrap() / b.trim().parse::<f32>().unwrap();
    }
    s.trim()
        .parse::<f32>()
        .unwrap_or_else(|_| panic!("not a number: {s}"))
}

#[test]
fn documented_defaults_equal_default_impl() {
    let src = include_str!("../src/physics_settings.rs");
    let d = PhysicsSettings::default();
    let mut pending: Option<String> = None;
    let mut checked = 0;
    for line in src.lines() {
        let t = line.trim();
        if let Some(rest) = t.strip_prefix("/// Default: `") {
            pending = Some(rest.split('`').next().unwrap().to_string());
        } else if let Some(rest) = t.strip_prefix("pub ") {
            // Fields only: methods (`precise_range_for(&self, size: f32)`) have no default.
            if rest.starts_with("fn ") {
                continue;
            }
            let Some((name, _)) = rest.split_once(':') else {
                continue;
            };
            let doc = pending
                .take()
                .unwrap_or_else(|| panic!("field {name} has no `Default:` doc line"));
            let ok = match name {
                "dt" => (parse_num(&doc) - d.dt).abs() < 1e-9,
                "gravity" => {
                    let v: Vec<f32> = doc
                        .trim_matches(|c| c == '(' || c == ')')
                        .split(',')
                        .map(parse_num)
                        .collect();
                    v == [d.gravity.x, d.gravity.y, d.gravity.z]
                }
                "substeps" => parse_num(&doc) as u32 == d.substeps,
                "solver_iterations" => parse_num(&doc) as u32 == d.solver_iterations,
                "relax_iterations" => parse_num(&doc) as u32 == d.relax_iterations,
                "contact_hertz" => parse_num(&doc) == d.contact_hertz,
                "contact_damping_ratio" => parse_num(&doc) == d.contact_damping_ratio,
                "max_contact_push_speed" => parse_num(&doc) == d.max_contact_push_speed,
                "max_penetration_fraction" => parse_num(&doc) == d.max_penetration_fraction,
                "max_support_mass_ratio" => parse_num(&doc) == d.max_support_mass_ratio,
                "linear_slop" => parse_num(&doc) == d.linear_slop,
                "speculative_distance" => parse_num(&doc) == d.speculative_distance,
                "max_speculative_distance" => parse_num(&doc) == d.max_speculative_distance,
                "aabb_margin" => parse_num(&doc) == d.aabb_margin,
                "restitution_threshold" => parse_num(&doc) == d.restitution_threshold,
                "static_friction_speed" => parse_num(&doc) == d.static_friction_speed,
                "max_linear_speed" => parse_num(&doc) == d.max_linear_speed,
                "max_angular_speed" => parse_num(&doc) == d.max_angular_speed,
                "max_position_spacing" => parse_num(&doc) == d.max_position_spacing,
                "sleep_enabled" => doc.parse::<bool>().unwrap() == d.sleep_enabled,
                "sleep_linear_threshold" => parse_num(&doc) == d.sleep_linear_threshold,
                "sleep_angular_threshold" => parse_num(&doc) == d.sleep_angular_threshold,
                "time_to_sleep" => parse_num(&doc) == d.time_to_sleep,
                "ccd_enabled" => doc.parse::<bool>().unwrap() == d.ccd_enabled,
                "joint_hertz" => parse_num(&doc) == d.joint_hertz,
                "joint_damping_ratio" => parse_num(&doc) == d.joint_damping_ratio,
                "grounded_min_normal_y" => parse_num(&doc) == d.grounded_min_normal_y,
                other => panic!("test does not know field {other}: add it"),
            };
            assert!(
                ok,
                "field {name}: documented default `{doc}` differs from Default::default() = {d:?}"
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 27, "every settings field checked");
}

#[test]
fn the_defaults_and_every_preset_validate() {
    use onyx_physics::PhysicsPreset;
    assert_eq!(PhysicsSettings::default().validate(), Ok(()));
    for p in PhysicsPreset::ALL {
        assert_eq!(p.settings().validate(), Ok(()), "{p}");
    }
}

#[test]
fn a_bad_field_is_named_with_its_value() {
    let s = PhysicsSettings {
        max_penetration_fraction: 1.5,
        ..Default::default()
    };
    let e = s.validate().expect_err("1.5 is not a fraction");
    assert_eq!(
        e.to_string(),
        "physics.max_penetration_fraction must be in (0, 1), got 1.5"
    );
    let s = PhysicsSettings {
        dt: f32::NAN,
        ..Default::default()
    };
    assert!(s.validate().is_err());
}
