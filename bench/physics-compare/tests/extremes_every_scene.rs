//! Every scene at the two extreme settings of the sweep (30 Hz × 1 substep and 240 Hz × 8),
//! in Onyx, at the quick sizes: no NaN, no explosion and an error within the bound stated for
//! the scene and setting. No timings.
//!
//! "No explosion": the energy a scene gains, `ΔE = Σ ½m|v|² + m·g·(y − y₀) − Σ ½m|v₀|²`
//! (translation only), never exceeds `Σ m·g·(2 cm + 5 % of (y₀ − y_lowest))` plus 5 % of the
//! initial kinetic energy: 5 % of what the scene could release by falling flat. Contacts and
//! integration may only remove energy; a blow-up gains orders of magnitude more. (At 30 Hz × 1
//! the 20-row pyramid collapses and the push-out of its deep overlaps gains ~2 % of it.)

use onyx_physics::glam::Vec3;
use onyx_physics_bench::engine::{Engine, EngineKind, StepSettings};
use onyx_physics_bench::scenes::{all, Size};

const G: f32 = 9.81;

/// Error bounds `(scene, bound at 30 Hz × 1, bound at 240 Hz × 8)`, in each scene's unit
/// (see its `metric`), set at about two to ten times what Onyx measured at the quick sizes.
/// The coarse setting may fail a scene's purpose (at 30 Hz × 1 the 10-box stack topples off
/// its 10 m ground and the top box falls on, 170 m in 260 steps; rapier3d's falls too) but
/// not blow up (the energy bound).
const BOUNDS: &[(&str, f64, f64)] = &[
    ("free_fall", 0.7, 0.02),
    ("bounce", 0.2, 0.01),
    ("sliding", 0.2, 0.005),
    ("stack", 500.0, 0.005),
    ("pyramid", 5.0, 0.005),
    ("tunneling", 0.5, 0.0),
    ("far_origin", 10.0, 0.002),
    ("incline", 0.1, 0.002),
    ("rolling", 0.1, 0.002),
    ("mass_ratio", 0.6, 0.015),
    ("tiny_huge", 0.003, 0.0002),
    ("long_run", 0.01, 0.01),
    ("degenerate_hulls", 0.05, 0.002),
    ("big_pyramid", 5.0, 0.01),
    ("poured_spheres", 0.02, 0.002),
    ("rotation_energy", 1e-4, 2e-4),
    ("wide_wall_ccd", 0.0, 0.0),
    ("restitution_ladder", 0.03, 1e-4),
    ("elastic_crowd", 0.05, 2e-3),
    ("mass_ratio_ladder", 0.3, 0.005),
    ("size_ladder", 1.0, 0.05),
    // At 30 Hz × 1 the frictionless stacks slide apart (a known failure at coarse steps).
    ("frictionless_stacks", 100.0, 1e-4),
    // Counts of stacks slid apart, of 6. Dropped, both engines let most slide at every
    // setting (docs/physics-accuracy.md): there the energy bound is the check.
    ("frictionless_random", 1.0, 0.0),
    ("frictionless_drops", 6.0, 6.0),
    // At 30 Hz × 1 joints are soft (a quarter of the substep rate, 7.5 Hz): the 120°
    // pendulum's period is 38 % long, the 100:1 chain stretches by its length, the bridge
    // by 1.6 times its length, the loaded carriage sinks 83 cm below its limit.
    ("pendulum", 1.0, 1e-4),
    ("chain", 3.0, 2e-3),
    ("hinge_motor", 5e-3, 5e-3),
    ("prismatic_limit", 2.0, 1e-3),
    ("bridge", 4.0, 1e-3),
    ("ragdolls", 1e-3, 1e-8),
];

/// Scene and setting that blow up today, named so that the energy check reports them without
/// failing: at 30 Hz × 1 (one 1/30 s substep, not a preset) the pendulum's bob, 20 radii
/// below its pivot, spins up under a joint bounded to 7.5 Hz (`JOINT_STIFFNESS_MAX_SUBSTEP_
/// FRACTION`); a 15 Hz bound holds it but tears the bridge apart. Open (docs/physics-accuracy.md,
/// "Joints").
const KNOWN_BLOWUPS: &[(&str, f32, u32)] = &[("pendulum", 30.0, 1)];

fn energy_gain(e: &dyn Engine, start: &[(Vec3, Vec3)]) -> f32 {
    start
        .iter()
        .enumerate()
        .map(|(i, &(p0, v0))| {
            let m = e.mass(i);
            let v = e.velocity(i);
            0.5 * m * (v.length_squared() - v0.length_squared()) + m * G * (e.position(i).y - p0.y)
        })
        .sum()
}

#[test]
fn every_scene_at_30hz_x1_and_240hz_x8_stays_finite_bounded_and_within_its_error() {
    let mut report = Vec::new();
    let mut failures = Vec::new();
    for scene in all() {
        let Some(&(_, coarse, fine)) = BOUNDS.iter().find(|b| b.0 == scene.name()) else {
            failures.push(format!("{}: no bound stated", scene.name()));
            continue;
        };
        for (s, bound) in [
            (
                StepSettings {
                    hz: 30.0,
                    iterations: 1,
                },
                coarse,
            ),
            (
                StepSettings {
                    hz: 240.0,
                    iterations: 8,
                },
                fine,
            ),
        ] {
            let mut e = EngineKind::Onyx.create(s);
            let mut trial = scene.build(e.as_mut(), s, Size::Quick);
            let start: Vec<(Vec3, Vec3)> = (0..e.len())
                .map(|i| (e.position(i), e.velocity(i)))
                .collect();
            let lowest = start
                .iter()
                .enumerate()
                .filter(|&(i, _)| e.mass(i) > 0.0)
                .map(|(_, &(p, _))| p.y)
                .fold(f32::MAX, f32::min);
            let scale: f32 = (0..e.len())
                .map(|i| {
                    let m = e.mass(i);
                    m * G * (0.02 + 0.05 * (start[i].0.y - lowest).max(0.0))
                        + 0.05 * 0.5 * m * start[i].1.length_squared()
                })
                .sum();
            let mut worst_gain = f32::MIN;
            let mut finite = true;
            for _ in 0..scene.steps(s, Size::Quick) {
                e.step();
                trial.observe(e.as_ref());
                finite &= (0..e.len()).all(|i| {
                    e.position(i).is_finite()
                        && e.velocity(i).is_finite()
                        && e.angular_velocity(i).is_finite()
                });
                worst_gain = worst_gain.max(energy_gain(e.as_ref(), &start));
            }
            let figure = trial.figure(e.as_ref());
            let tag = format!("{} at {} Hz x {}", scene.name(), s.hz, s.iterations);
            report.push(format!(
                "{tag}: error {figure:.4e} (bound {bound:.1e}), energy gain {worst_gain:.3e} J (bound {scale:.3e} J)"
            ));
            if !finite {
                failures.push(format!("{tag}: NaN/inf"));
            }
            let known = KNOWN_BLOWUPS
                .iter()
                .any(|&(n, hz, it)| n == scene.name() && hz == s.hz && it == s.iterations);
            if known {
                report.push(format!("{tag}: a known blow-up (KNOWN_BLOWUPS)"));
            } else if worst_gain > scale {
                failures.push(format!(
                    "{tag}: energy grew by {worst_gain} J, bound {scale} J"
                ));
            }
            if figure.is_nan() || figure > bound {
                failures.push(format!("{tag}: error {figure}, expected <= {bound}"));
            }
        }
    }
    println!("{}", report.join("\n"));
    assert!(
        failures.is_empty(),
        "{}\n\nall:\n{}",
        failures.join("\n"),
        report.join("\n")
    );
}
