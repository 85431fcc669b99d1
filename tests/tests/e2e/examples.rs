//! Every example in `examples/` (each a lesson, see `examples/README.md`), loaded from disk as
//! the built library into a headless host, run for a few frames and checked for what it
//! shows. Screenshots are small: lavapipe draws them on the CPU.

use onyx_plugin_api::egui::pos2;
use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::{InputEvent, Key, MeshId, MeshRenderer, MouseButton, Name, Transform};
use onyx_runtime::world::PluginComponents;
use onyx_runtime::{HeadlessHost, PluginStatus};
use onyx_tests::plugin_library;
use serde_json::Value;

/// A headless host running the built examples `crates` (crate names, in load order).
fn example_host(crates: &[&str]) -> HeadlessHost {
    let mut host = HeadlessHost::new();
    for name in crates {
        host.load_plugin_file(&plugin_library(name))
            .unwrap_or_else(|e| panic!("example {name} loads: {e}"));
    }
    host
}

/// Asserts every plugin of `host` is still running.
fn assert_running(host: &HeadlessHost) {
    for plugin in host.host().plugins() {
        assert_eq!(
            plugin.status(),
            &PluginStatus::Running,
            "plugin `{}`",
            plugin.name()
        );
    }
}

fn transform(host: &HeadlessHost, name: &str) -> Transform {
    host.find::<Transform>(name)
        .unwrap_or_else(|| panic!("no entity `{name}`"))
        .1
}

/// The plugin component `component` of the entity named `name`, as JSON.
fn component(host: &HeadlessHost, name: &str, component: &str) -> Value {
    let (entity, _) = host
        .find::<Name>(name)
        .unwrap_or_else(|| panic!("no entity `{name}`"));
    let blobs: PluginComponents = host.get(entity).expect("it has plugin components");
    let blob = &blobs.0[component];
    serde_json::from_slice(&blob.bytes).expect("a JSON component")
}

/// The share of pixels of `image` near `rgb` (each channel within 40).
fn share_near(image: &onyx_render::image::RgbaImage, rgb: [u8; 3]) -> f64 {
    let near = image
        .pixels()
        .filter(|p| (0..3).all(|c| p.0[c].abs_diff(rgb[c]) <= 40))
        .count();
    near as f64 / f64::from(image.width() * image.height())
}

#[test]
fn first_plugin_draws_a_lit_cube_that_turns() {
    let mut host = example_host(&["first-plugin"]);
    host.step(2);
    let start = transform(&host, "cube").rotation;
    host.step(30);
    let turned = transform(&host, "cube").rotation.angle_between(start);
    assert!(
        (turned - 0.5).abs() < 0.02,
        "half a radian in 0.5 s: {turned}"
    );
    let image = host.screenshot(160, 120).expect("lavapipe renders");
    let [r, g, b, _] = image.get_pixel(80, 60).0;
    assert!(
        r > 120 && r > g && g > b,
        "an orange cube in the middle: {r},{g},{b}"
    );
    let sky = image.get_pixel(2, 2).0;
    assert_ne!(
        sky,
        image.get_pixel(80, 60).0,
        "and something else around it"
    );
    assert_running(&host);
}

#[test]
fn camera_controller_flies_forward_on_w_turns_on_a_right_drag_and_quits_on_escape() {
    let mut host = example_host(&["camera-controller"]);
    host.step(2);
    let start = transform(&host, "camera");
    host.hold_key(Key::W, true);
    host.step(30);
    host.hold_key(Key::W, false);
    host.step(1);
    let flown = transform(&host, "camera");
    let forward = start.rotation * Vec3::NEG_Z;
    let travelled = (flown.translation - start.translation).dot(forward);
    assert!(
        (travelled - 2.0).abs() < 0.2,
        "4 m/s for 0.5 s: {travelled} m"
    );

    // Looking goes by the mouse's own motion (raw, as a window reports it), not the cursor.
    host.hold_button(MouseButton::Right, true);
    for _ in 0..3 {
        host.inject(InputEvent::MouseMotion { dx: 20.0, dy: 0.0 });
        host.step(1);
    }
    host.hold_button(MouseButton::Right, false);
    host.step(1);
    let turned = transform(&host, "camera")
        .rotation
        .angle_between(flown.rotation);
    assert!(turned > 0.1, "a 60-pixel drag turned the view {turned} rad");

    host.press_key(Key::Escape);
    host.step(1);
    assert!(host.quit_requested(), "Escape quits");
}

#[test]
fn gui_spawner_spawns_a_body_per_click_and_clears_them() {
    let mut host = example_host(&["gui-spawner"]);
    host.step(2);
    let bodies = |host: &HeadlessHost| {
        host.world()
            .query::<&Name>()
            .iter()
            .filter(|n| n.as_str().starts_with("Cube "))
            .count()
    };
    for _ in 0..3 {
        assert!(host.click_widget("Spawn"), "a Spawn button");
        host.step(1);
    }
    assert_eq!(bodies(&host), 3);
    assert!(
        host.find_widget("3 bodies").is_some(),
        "the window counts them"
    );
    // They fall onto the ground and stay there.
    host.step(120);
    let y = transform(&host, "Cube 1").translation.y;
    assert!((0.4..0.7).contains(&y), "resting on the ground at y = {y}");
    assert!(host.click_widget("Clear"));
    host.step(1);
    assert_eq!(bodies(&host), 0);
    assert_running(&host);
}

#[test]
fn events_ping_and_pong_answer_each_other_and_ping_alone_hears_nothing() {
    let mut host = example_host(&["events-ping", "events-pong"]);
    host.step(60 * 3 + 5);
    let ping = component(&host, "ping ball", "events_ping.tally");
    let pong = component(&host, "pong ball", "events_pong.tally");
    assert_eq!(ping["sent"], 3, "{ping}");
    assert_eq!(ping["answered"], 3, "every ping answered: {ping}");
    assert_eq!(pong["heard"], 3, "{pong}");
    assert_eq!(pong["from"], "events_ping", "the sender is named: {pong}");

    let mut alone = example_host(&["events-ping"]);
    alone.step(60 * 2 + 5);
    let ping = component(&alone, "ping ball", "events_ping.tally");
    assert_eq!(
        (ping["sent"].as_u64(), ping["answered"].as_u64()),
        (Some(2), Some(0))
    );
    assert_running(&host);
}

#[test]
fn physics_playground_reports_contacts_shoves_what_is_clicked_and_rolls_the_ball() {
    let mut host = example_host(&["physics-playground"]);
    host.step(30);
    let stats = component(&host, "stats", "physics_playground.stats");
    assert!(
        stats["contacts"].as_u64() >= Some(6),
        "the boxes touch the ground and each other: {stats}"
    );
    let before = transform(&host, "box 1.1");
    // The middle of the view is the second row's right box.
    host.click_at(pos2(640.0, 360.0));
    host.step(20);
    let stats = component(&host, "stats", "physics_playground.stats");
    assert_eq!(stats["shoves"], 1, "{stats}");
    let after = transform(&host, "box 1.1");
    assert!(
        after.translation.z < before.translation.z - 0.05,
        "the clicked box was pushed away from the camera: {before:?} -> {after:?}"
    );

    let ball = transform(&host, "ball").translation;
    host.hold_key(Key::ArrowLeft, true);
    host.step(30);
    host.hold_key(Key::ArrowLeft, false);
    let rolled = transform(&host, "ball").translation;
    assert!(rolled.x < ball.x - 0.1, "rolled left: {ball} -> {rolled}");
    assert_running(&host);
}

#[test]
fn procedural_mesh_draws_its_terrain_and_the_balls_rest_on_it() {
    let mut host = example_host(&["procedural-mesh"]);
    host.step(2);
    let (terrain, _) = host.find::<Transform>("terrain").expect("the terrain");
    let look: MeshRenderer = host.get(terrain).expect("drawn");
    assert!(
        MeshId::BUILTIN.iter().all(|(id, _)| *id != look.mesh),
        "a generated mesh, not a built-in shape"
    );
    host.step(150);
    for i in 0..5 {
        let y = transform(&host, &format!("ball {i}")).translation.y;
        assert!(
            (-0.3..1.4).contains(&y),
            "ball {i} rests on the terrain, y = {y}"
        );
    }
    let image = host.screenshot(160, 120).expect("lavapipe renders");
    let green = share_near(&image, [95, 165, 85]) + share_near(&image, [60, 120, 55]);
    assert!(
        green > 0.05,
        "the green terrain fills part of the view: {green}"
    );
    assert_running(&host);
}

#[test]
fn hot_reload_keeps_the_angle_and_turns_across_a_reload() {
    let dir = tempfile::tempdir().unwrap();
    let library = dir
        .path()
        .join(onyx_runtime::plugins::plugin_search::library_file_name(
            "hot_reload",
        ));
    std::fs::copy(plugin_library("hot-reload"), &library).unwrap();
    let mut host = HeadlessHost::new();
    host.load_plugin_file(&library).expect("loads");
    host.step(45);
    let before = transform(&host, "cube").rotation;
    host.host_mut()
        .reload_plugin("hot_reload")
        .expect("reloads");
    host.step(1);
    let after = transform(&host, "cube").rotation;
    let moved = after.angle_between(before);
    assert!(
        moved < 0.05,
        "the cube goes on from where it was, not from 0: moved {moved} rad"
    );
    assert_eq!(
        host.host().plugin("hot_reload").map(|p| p.reloads()),
        Some(1)
    );
    assert_eq!(
        host.world()
            .query::<&Name>()
            .iter()
            .filter(|n| n.as_str() == "cube")
            .count(),
        1,
        "no second cube: on_init is not run again for a reload"
    );
    assert_running(&host);
}

/// `scripts/example.sh` lists and runs the examples from a table of its own: every example
/// crate's plugin must be in it, and every plugin it names must be an example crate's.
#[test]
fn the_example_script_lists_every_example_and_runs_only_those() {
    let repo = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let crates: Vec<String> = std::fs::read_dir(repo.join("examples"))
        .unwrap()
        .flatten()
        .filter(|e| e.path().join("Cargo.toml").is_file())
        .map(|e| e.file_name().to_string_lossy().replace('-', "_"))
        .collect();
    let script = std::fs::read_to_string(repo.join("scripts/example.sh")).unwrap();
    let rows: Vec<(&str, Vec<&str>)> = script
        .lines()
        .filter_map(|l| l.trim().strip_prefix('"')?.strip_suffix('"'))
        .filter_map(|row| {
            let mut fields = row.split('|');
            let name = fields.next()?;
            let plugins = fields.next()?.split_whitespace().collect();
            Some((name, plugins))
        })
        .collect();
    for lib in &crates {
        assert!(
            rows.iter()
                .any(|(_, plugins)| plugins.contains(&lib.as_str())),
            "examples/{lib} is not in scripts/example.sh"
        );
    }
    for (name, plugins) in &rows {
        for plugin in plugins {
            assert!(
                crates.iter().any(|c| c == plugin),
                "scripts/example.sh runs `{plugin}` ({name}), which is no example crate"
            );
        }
    }
    let out = std::process::Command::new("bash")
        .arg(repo.join("scripts/example.sh"))
        .output()
        .expect("bash runs");
    let listed = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{listed}");
    for (name, _) in &rows {
        assert!(
            listed.contains(&format!("  {name} ")),
            "{name} listed: {listed}"
        );
    }
    let unknown = std::process::Command::new("bash")
        .arg(repo.join("scripts/example.sh"))
        .arg("no-such-example")
        .output()
        .expect("bash runs");
    assert_eq!(unknown.status.code(), Some(2));
}

#[test]
fn character_walks_up_the_stairs_on_w_and_jumps_on_space() {
    let mut host = example_host(&["character"]);
    host.step(5);
    let start = transform(&host, "character").translation;
    // 3 m/s for 2.5 s along -Z: over the 5 steps of 20 cm (from z = -3 to -5.5) onto the
    // landing 1 m up.
    host.hold_key(Key::W, true);
    host.step(150);
    host.hold_key(Key::W, false);
    host.step(5);
    assert_running(&host);
    let on_top = transform(&host, "character").translation;
    let standing = 0.5 + 0.3 + 0.01;
    assert!(
        on_top.z < -6.0 && on_top.z > -9.5 && (on_top.y - (1.0 + standing)).abs() < 0.02,
        "the character climbed from {start} onto the landing (y = {}): it is at {on_top}",
        1.0 + standing
    );
    let camera = transform(&host, "camera").translation;
    assert!(
        (camera - on_top - Vec3::new(0.0, 3.0, 7.0)).length() < 0.05,
        "the camera follows: {camera}"
    );
    host.hold_key(Key::Space, true);
    host.step(2);
    host.hold_key(Key::Space, false);
    host.step(10);
    let jumped = transform(&host, "character").translation.y - on_top.y;
    assert!(jumped > 0.2, "Space jumps: {jumped} m up after 0.2 s");
}

#[test]
fn joints_open_the_door_hang_the_chain_hold_the_ragdoll_and_count_the_zone() {
    let mut host = example_host(&["joints"]);
    host.step(240); // 4 s at 60 Hz
    assert_running(&host);
    // The door's servo swings it to 90° about the vertical hinge.
    let door = transform(&host, "door");
    let side = door.rotation * Vec3::X;
    let angle = (-side.z).atan2(side.x);
    assert!(
        (angle - std::f32::consts::FRAC_PI_2).abs() < 0.05,
        "the door is at {angle} rad"
    );
    let hinge = door.translation + door.rotation * Vec3::new(-0.5, 0.0, 0.0);
    assert!(
        (hinge - Vec3::new(0.05, 1.1, 0.0)).length() < 0.01,
        "hinge at {hinge}"
    );
    // Each chain link's ends stay on the next link's while the chain still swings: within
    // 2 % of a link (the swinging tip, fastest, measured 3.5 mm at balanced).
    let half = 0.15;
    let mut previous_end = Vec3::new(-4.0, 5.0, 0.0);
    for k in 0..10 {
        let t = transform(&host, &format!("link {k}"));
        let back = t.translation + t.rotation * Vec3::new(-half, 0.0, 0.0);
        assert!(
            (back - previous_end).length() < 0.006,
            "link {k} is {} m off its joint",
            (back - previous_end).length()
        );
        previous_end = t.translation + t.rotation * Vec3::new(half, 0.0, 0.0);
    }
    // The ragdoll fell to the ground with every limb still on its joint.
    let torso = transform(&host, "torso");
    assert!(
        torso.translation.y < 1.0,
        "the ragdoll did not fall: {}",
        torso.translation
    );
    for (name, offset, on_torso) in [
        ("head", Vec3::new(0.0, 0.55, 0.0), Vec3::new(0.0, 0.35, 0.0)),
        (
            "left arm",
            Vec3::new(-0.55, 0.15, 0.0),
            Vec3::new(-0.25, 0.2, 0.0),
        ),
        (
            "left leg",
            Vec3::new(-0.12, -0.7, 0.0),
            Vec3::new(-0.12, -0.35, 0.0),
        ),
    ] {
        let limb = transform(&host, name);
        let on_limb = limb.translation + limb.rotation * (on_torso - offset);
        let on_body = torso.translation + torso.rotation * on_torso;
        assert!(
            (on_limb - on_body).length() < 0.01,
            "{name} is {} m off its joint",
            (on_limb - on_body).length()
        );
    }
    // The ball fell through the zone: in once, out once.
    let stats = component(&host, "zone", "joints.zone");
    assert_eq!(stats["entered"], 1, "{stats}");
    assert_eq!(stats["exited"], 1, "{stats}");
}
