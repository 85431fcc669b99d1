//! The physics scene files in `assets/scenes/physics/`, loaded into a host and checked
//! against what physics says (the same scenes are measured across settings, next to
//! rapier3d, by `bench/physics-compare`).

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::{Name, RigidBody, Transform};
use onyx_runtime::HeadlessHost;

const G: f32 = 9.81;

fn scene(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../assets/scenes/physics/{name}.ron"))
}

fn load(name: &str) -> HeadlessHost {
    let mut host = HeadlessHost::new();
    host.load_scene(&scene(name)).unwrap();
    // One frame per fixed step, whatever the scene's preset.
    let dt = host.host_mut().clock_mut().fixed_delta();
    host.set_frame_time(dt);
    host
}

/// Every named dynamic body and its position.
fn bodies(host: &HeadlessHost) -> HashMap<String, Vec3> {
    host.world()
        .query::<(&Name, &Transform, &RigidBody)>()
        .iter()
        .map(|(n, t, _)| (n.as_str().to_owned(), t.translation))
        .collect()
}

#[test]
fn bounce_ladder_balls_rebound_to_e_squared_of_the_drop() {
    let mut host = load("bounce_ladder");
    let dt = host.host_mut().clock_mut().fixed_delta() as f32;
    let restitutions = [0.2f32, 0.4, 0.6, 0.8, 1.0];
    let name = |e: f32| format!("ball e={e:.1}");
    let drop = 1.75; // bottom of each ball above the ground
    let radius = 0.5;
    // Per ball: fell (bounced once), highest centre after the bounce.
    let mut state: Vec<(bool, f32, f32)> = vec![(false, f32::MIN, 2.25); 5];
    for _ in 0..150 {
        host.step(1);
        for (i, e) in restitutions.iter().enumerate() {
            let (_, t) = host.find::<Transform>(&name(*e)).unwrap();
            let (_, rb) = host.find::<RigidBody>(&name(*e)).unwrap();
            let s = &mut state[i];
            if !s.0 && rb.linear_velocity.y > 0.0 && t.translation.y < 1.0 {
                s.0 = true;
            }
            if s.0 {
                s.1 = s.1.max(t.translation.y);
            }
            s.2 = s.2.min(t.translation.y);
        }
    }
    for (i, e) in restitutions.iter().enumerate() {
        let (bounced, apex, lowest) = state[i];
        assert!(bounced, "ball e={e} never bounced");
        let expected = radius + e * e * drop;
        // The rebound speed is e times the speed at the start of the step in which the ball
        // lands, up to g·dt less than at impact: the height is short by up to 2·g·dt/v of it.
        let v = (2.0 * G * drop).sqrt();
        let tolerance = 2.0 * G * dt / v * e * e * drop + 0.01;
        assert!(
            (apex - expected).abs() < tolerance,
            "ball e={e}: rebound apex {apex:.3} m, physics says {expected:.3} m"
        );
        assert!(
            lowest > radius - 0.05,
            "ball e={e} sank to {lowest:.3} m into the ground"
        );
    }
}

#[test]
fn incline_ladder_blocks_slide_iff_mu_is_below_tan_theta_at_the_right_rate() {
    let mut host = load("incline_ladder");
    let start = bodies(&host);
    let seconds = 1.0f32;
    let steps = (f64::from(seconds) / host.host_mut().clock_mut().fixed_delta()).round() as u32;
    host.step(steps);
    let end = bodies(&host);
    let theta = 30f32.to_radians();
    for mu in [0.1f32, 0.3, 0.5, 0.7, 0.9] {
        let name = format!("block mu={mu:.1}");
        let moved = (end[&name] - start[&name]).length();
        let a = G * (theta.sin() - mu * theta.cos());
        if a > 0.0 {
            let expected = 0.5 * a * seconds * seconds;
            assert!(
                (moved - expected).abs() < 0.1 * expected + 0.01,
                "{name}: slid {moved:.3} m in {seconds} s, physics says {expected:.3} m"
            );
        } else {
            assert!(moved < 0.01, "{name}: should stick, moved {moved:.4} m");
        }
    }
}

#[test]
fn a_twenty_row_pyramid_stands() {
    let mut host = load("pyramid");
    let start = bodies(&host);
    assert_eq!(start.len(), 210);
    host.step(180);
    let end = bodies(&host);
    let (worst, name) = start
        .iter()
        .map(|(n, p)| ((end[n] - *p).length(), n.clone()))
        .fold(
            (0.0f32, String::new()),
            |a, b| if b.0 > a.0 { b } else { a },
        );
    assert!(worst < 0.05, "{name} moved {worst:.3} m");
}
