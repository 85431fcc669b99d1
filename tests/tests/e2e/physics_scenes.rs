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

/// Steps for `seconds` of simulated time at the scene's fixed rate.
fn steps_for(host: &mut HeadlessHost, seconds: f64) -> u32 {
    (seconds / host.host_mut().clock_mut().fixed_delta()).round() as u32
}

fn position(host: &HeadlessHost, name: &str) -> Vec3 {
    host.find::<Transform>(name)
        .unwrap_or_else(|| panic!("no entity {name:?} in the scene"))
        .1
        .translation
}

#[test]
fn free_fall_drops_half_g_t_squared() {
    let mut host = load("free_fall");
    let steps = steps_for(&mut host, 2.0);
    host.step(steps);
    let y = position(&host, "ball").y;
    let expected = 100.0 - 0.5 * G * 2.0 * 2.0;
    // Semi-implicit Euler at 60 Hz x 4 falls g·h·t/2 ≈ 4 cm further in 2 s.
    assert!(
        (y - expected).abs() < 0.05,
        "ball at {y:.3} m after 2 s, physics says {expected:.3} m"
    );
}

#[test]
fn sliding_ladder_boxes_stop_after_v2_over_2_mu_g() {
    let mut host = load("sliding_ladder");
    let start = bodies(&host);
    let steps = steps_for(&mut host, 3.0);
    host.step(steps);
    let end = bodies(&host);
    for mu in [0.2f32, 0.5, 0.8] {
        let name = format!("box mu={mu:.1}");
        let (_, rb) = host.find::<RigidBody>(&name).unwrap();
        assert!(
            rb.linear_velocity.length() < 0.01,
            "{name} still moving at {} after 3 s",
            rb.linear_velocity
        );
        let slid = end[&name].x - start[&name].x;
        let expected = 5.0 * 5.0 / (2.0 * mu * G);
        assert!(
            (slid - expected).abs() < 0.03 * expected,
            "{name}: stopped after {slid:.3} m, physics says {expected:.3} m"
        );
    }
}

#[test]
fn rolling_ball_accelerates_at_five_sevenths_g_sin_theta_and_turns_at_v_over_r() {
    let mut host = load("rolling");
    let start = position(&host, "ball");
    let steps = steps_for(&mut host, 1.0);
    host.step(steps);
    let moved = (position(&host, "ball") - start).length();
    let a = 5.0 / 7.0 * G * 20f32.to_radians().sin();
    let expected = 0.5 * a;
    assert!(
        (moved - expected).abs() < 0.03 * expected,
        "rolled {moved:.3} m in 1 s, physics says {expected:.3} m"
    );
    let (_, rb) = host.find::<RigidBody>("ball").unwrap();
    let (v, w) = (rb.linear_velocity.length(), rb.angular_velocity.length());
    assert!(
        (w * 0.5 - v).abs() < 0.05 * v,
        "rolls at {v:.3} m/s turning at {w:.3} rad/s: slipping (ω r = {:.3})",
        w * 0.5
    );
}

#[test]
fn a_twenty_box_stack_stands_for_a_thousand_steps() {
    let mut host = load("tall_stack");
    assert_eq!(bodies(&host).len(), 20);
    // Soft contacts compress under the weight above them (the lowest carries 19 boxes), so
    // the stack first settles by a few centimetres; from then on it must hold still.
    host.step(60);
    let settled = bodies(&host);
    let sink = 19.5 - settled["box 19"].y;
    assert!(
        (0.0..0.15).contains(&sink),
        "the top box settled {sink:.4} m below its rigid height"
    );
    host.step(1000);
    let end = bodies(&host);
    for (name, p0) in &settled {
        let drift = (end[name] - *p0).length();
        assert!(drift < 0.01, "{name} drifted {drift:.4} m over 1,000 steps");
    }
}

#[test]
fn a_plank_four_hundred_times_heavier_rests_on_light_cubes() {
    let mut host = load("mass_ratio");
    let steps = steps_for(&mut host, 2.0);
    host.step(steps);
    let (_, plank) = host.find::<Transform>("plank").unwrap();
    let sink = 0.75 - plank.translation.y;
    // Soft contacts give under load; the precise preset holds it to ~2.6 cm (benchmark).
    assert!(
        (-0.005..0.04).contains(&sink),
        "the plank sank {sink:.4} m below y = 0.75"
    );
    let tilt = plank
        .rotation
        .angle_between(onyx_plugin_api::glam::Quat::IDENTITY);
    assert!(tilt < 0.01, "the plank tipped by {tilt:.4} rad");
    for cube in ["cube left", "cube right"] {
        let p = position(&host, cube);
        assert!(
            (p.x.abs() - 0.9).abs() < 0.01 && p.z.abs() < 0.01,
            "{cube} was squeezed out to {p}"
        );
    }
}

#[test]
fn no_bullet_with_ccd_passes_the_thin_wall() {
    let mut host = load("tunneling");
    let steps = steps_for(&mut host, 0.25);
    host.step(steps);
    for speed in (50..=500).step_by(50) {
        let name = format!("bullet {speed}");
        let x = position(&host, &name).x;
        assert!(x < 0.0, "{name} went through the wall: x = {x:.3} m");
        assert!(x > -0.2, "{name} never reached the wall: x = {x:.3} m");
    }
}

#[test]
fn a_stack_one_hundred_kilometres_out_stands_as_the_one_at_the_origin() {
    let mut host = load("far_origin");
    let start = bodies(&host);
    host.step(300);
    let end = bodies(&host);
    for i in 0..5 {
        let (near, far) = (format!("origin box {i}"), format!("far box {i}"));
        let near_moved = end[&near] - start[&near];
        let far_moved = end[&far] - start[&far];
        assert!(near_moved.length() < 0.01, "{near} moved {near_moved}");
        // Two f32 position quanta at 1e5 m (7.8 mm each).
        assert!(
            (far_moved - near_moved).length() < 0.02,
            "{far} moved {far_moved}, the same box at the origin {near_moved}"
        );
    }
}

#[test]
fn centimetre_beads_and_a_crate_on_a_ten_kilometre_block_rest_where_they_are() {
    let mut host = load("tiny_huge");
    let steps = steps_for(&mut host, 2.0);
    host.step(steps);
    for i in 0..10 {
        let name = format!("bead {i}");
        let p = position(&host, &name);
        assert!(
            (p.y - 0.005).abs() < 2e-4,
            "{name} at y = {:.6} m, resting height 0.005 m",
            p.y
        );
        assert!(
            (p.x - (-2.0 + 0.4 * i as f32)).abs() < 1e-3,
            "{name} rolled to x = {}",
            p.x
        );
    }
    let crate_y = position(&host, "crate").y;
    assert!(
        (crate_y - 0.5).abs() < 1e-3,
        "crate at y = {crate_y:.5} m, resting height 0.5 m"
    );
}
