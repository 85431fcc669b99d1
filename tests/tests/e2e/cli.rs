//! The `onyx` binary: exit codes, one-line reasons, `--dump-state`, help, and a real window
//! under Xvfb.

use std::path::Path;
use std::process::{Command, Output};

use onyx_tests::cli::{assert_exit, onyx, stderr};
use onyx_tests::{onyx_binary, onyx_in_xvfb, target_dir};

fn read_json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn entity<'a>(dump: &'a serde_json::Value, name: &str) -> &'a serde_json::Value {
    dump["entities"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["name"] == name)
        .unwrap_or_else(|| panic!("no entity `{name}` in {dump:#}"))
}

#[test]
fn headless_run_quits_when_hello_is_asked_and_dumps_the_state() {
    let dir = tempfile::tempdir().unwrap();
    let dump_path = dir.path().join("state.json");
    let dump = dump_path.to_str().unwrap();
    let out = onyx(&[
        "run",
        "--headless",
        "--plugin",
        "hello",
        "--plugin",
        "spinner",
        "--plugin",
        "fixture_faulty",
        "--set",
        "hello.quit_after=5",
        "--frames",
        "1000",
        "--dump-state",
        dump,
    ]);
    assert!(
        out.status.success(),
        "exit {:?}: {}",
        out.status,
        stderr(&out)
    );
    let state = read_json(&dump_path);
    assert_eq!(state["time"]["frame"], 5, "hello quit after 5 frames");
    let hello = entity(&state, "hello");
    assert_eq!(hello["components"]["hello.stats"]["updates"], 5);
    assert_eq!(hello["components"]["Name"], "hello");
    assert!(hello["id"].is_u64());
    // Built-in components field by field.
    let spin = entity(&state, "spinner 0");
    let t = &spin["components"]["Transform"];
    assert_eq!(t["translation"].as_array().unwrap().len(), 3);
    assert_eq!(t["rotation"].as_array().unwrap().len(), 4);
    assert_eq!(t["scale"], serde_json::json!([1.0, 1.0, 1.0]));
    // Plugin components: decoded when serde, base64 when raw.
    assert_eq!(spin["components"]["spinner.spin"]["speed"], 1.0);
    let faulty = entity(&state, "faulty");
    assert_eq!(
        faulty["components"]["fixture_faulty.updates"]["base64"],
        "BQAAAA=="
    );
    let plugins: Vec<&str> = state["plugins"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["status"].as_str().unwrap())
        .collect();
    assert_eq!(plugins, ["running"; 3]);
}

#[test]
fn fixed_hz_sets_the_step_rate() {
    let dir = tempfile::tempdir().unwrap();
    let dump_path = dir.path().join("state.json");
    let out = onyx(&[
        "run",
        "--headless",
        "--fixed-hz",
        "120",
        "--frames",
        "12",
        "--dump-state",
        dump_path.to_str().unwrap(),
    ]);
    assert_exit(&out, 0);
    let state = read_json(&dump_path);
    assert_eq!(state["time"]["ticks"], 12);
    assert!((state["time"]["fixed_delta"].as_f64().unwrap() - 1.0 / 120.0).abs() < 1e-6);
}

#[test]
fn an_unknown_plugin_fails_with_exit_2_and_one_line() {
    let out = onyx(&[
        "run",
        "--headless",
        "--frames",
        "1",
        "--plugin",
        "does_not_exist",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    let reason: Vec<&str> = err.lines().filter(|l| l.starts_with("onyx:")).collect();
    assert_eq!(reason.len(), 1, "{err}");
    assert!(
        reason[0].contains("plugin `does_not_exist` not found"),
        "{err}"
    );
}

#[test]
fn a_plugin_fault_during_the_run_gives_exit_1_and_still_dumps() {
    let dir = tempfile::tempdir().unwrap();
    let dump_path = dir.path().join("state.json");
    let out = onyx(&[
        "run",
        "--headless",
        "--frames",
        "3",
        "--plugin",
        "fixture_faulty",
        "--set",
        "fixture_faulty.panic_in=on_update",
        "--dump-state",
        dump_path.to_str().unwrap(),
    ]);
    assert_exit(&out, 1);
    let err = stderr(&out);
    assert!(
        err.lines()
            .any(|l| l.starts_with("onyx: plugin `fixture_faulty` faulted in on_update")),
        "{err}"
    );
    let state = read_json(&dump_path);
    assert_eq!(state["plugins"][0]["status"], "faulted");
    assert_eq!(state["plugins"][0]["stage"], "on_update");
}

#[test]
fn a_malformed_scene_fails_with_its_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("bad.ron");
    std::fs::write(&scene, "(version: 1,\n entities: [ (name: Some(\"x\") ]\n)").unwrap();
    let out = onyx(&[
        "run",
        "--headless",
        "--frames",
        "1",
        "--scene",
        scene.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("is malformed at line 2, column"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn every_subcommand_has_help() {
    for args in [&["--help"][..], &["run", "--help"], &["plugins", "--help"]] {
        let out = onyx(args);
        assert!(out.status.success(), "{args:?}: {}", stderr(&out));
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.contains("Usage: onyx"), "{args:?}: {text}");
    }
    let run_help = String::from_utf8_lossy(&onyx(&["run", "--help"]).stdout).into_owned();
    for flag in [
        "--plugin",
        "--scene",
        "--headless",
        "--frames",
        "--fixed-hz",
        "--dump-state",
        "ONYX_PLUGIN_PATH",
    ] {
        assert!(run_help.contains(flag), "run --help lacks {flag}");
    }
}

#[test]
fn plugins_lists_the_search_path_and_what_it_finds() {
    let out = onyx(&["plugins"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains(&target_dir().display().to_string()) && text.contains("    spinner"),
        "{text}"
    );
}

/// `onyx plugins` listed `target/debug` twice (as the executable's folder and as
/// `./target/debug`) and showed the test suite's fixture libraries as plugins.
#[test]
fn plugins_lists_each_folder_once_and_no_test_fixtures() {
    let out = Command::new(onyx_binary())
        .arg("plugins")
        .current_dir(repo_root())
        .env_remove("ONYX_PLUGIN_PATH")
        .env_remove("CARGO_TARGET_DIR")
        .output()
        .expect("onyx runs");
    assert_exit(&out, 0);
    let text = String::from_utf8_lossy(&out.stdout);
    let folders: Vec<std::path::PathBuf> = text
        .lines()
        .filter(|l| l.starts_with("  ") && !l.starts_with("    "))
        .map(|l| {
            let dir = repo_root().join(l.trim());
            dir.canonicalize().unwrap_or(dir)
        })
        .collect();
    for (i, dir) in folders.iter().enumerate() {
        assert!(
            !folders[..i].contains(dir),
            "{} listed twice:\n{text}",
            dir.display()
        );
    }
    assert!(text.contains("    editor"), "{text}");
    assert!(!text.contains("    fixture_"), "fixtures listed:\n{text}");
}

/// Log lines written to a file or a pipe carried ANSI colour codes.
#[test]
fn logs_to_a_pipe_have_no_colour_codes() {
    let out = Command::new(onyx_binary())
        .args(["run", "--headless", "--frames", "3", "--plugin", "hello"])
        .env("ONYX_PLUGIN_PATH", target_dir())
        .env("RUST_LOG", "info")
        .env_remove("NO_COLOR")
        .output()
        .expect("onyx runs");
    let err = stderr(&out);
    assert!(out.status.success(), "{err}");
    assert!(err.contains("INFO"), "info lines were logged: {err}");
    assert!(!err.contains('\u{1b}'), "colour codes in a pipe: {err:?}");
}

/// A real window: winit under Xvfb opens it, the host runs frames in it, resizes reach the
/// plugins, and it closes cleanly when the run ends.
#[test]
fn a_window_opens_runs_frames_and_closes_cleanly_under_xvfb() {
    let dir = tempfile::tempdir().unwrap();
    let dump_path = dir.path().join("state.json");
    let out = onyx_in_xvfb()
        .args([
            "run",
            "--plugin",
            "hello",
            "--frames",
            "20",
            "--size",
            "640x360",
            "--no-vsync",
            "--dump-state",
        ])
        .arg(&dump_path)
        .env("RUST_LOG", "info")
        .output()
        .expect("xvfb-run runs");
    assert!(
        out.status.success(),
        "exit {:?}: {}",
        out.status,
        stderr(&out)
    );
    let err = stderr(&out);
    assert!(err.contains("window opened"), "{err}");
    let state = read_json(&dump_path);
    let stats = &entity(&state, "hello")["components"]["hello.stats"];
    assert_eq!(stats["updates"], 20);
    assert!(
        stats["resizes"].as_u64().unwrap() >= 1,
        "the window's size never reached on_resize: {stats}"
    );
    assert!(err.contains("hello from on_resize: 640x360"), "{err}");
    assert!(
        err.contains("goodbye after 20 frames"),
        "on_detach ran: {err}"
    );
}

fn repo_root() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn showcase_screenshot(windowed: bool, path: &Path) -> Output {
    let onyx = onyx_binary();
    let mut args: Vec<String> = vec![
        "run".into(),
        "--plugin".into(),
        "showcase".into(),
        "--frames".into(),
        "30".into(),
        "--size".into(),
        "320x200".into(),
        "--screenshot".into(),
        path.display().to_string(),
    ];
    let mut command = if windowed {
        onyx_in_xvfb()
    } else {
        args.insert(1, "--headless".into());
        Command::new(onyx)
    };
    command
        .args(&args)
        .current_dir(repo_root())
        .env("ONYX_PLUGIN_PATH", target_dir())
        .env_remove("WAYLAND_DISPLAY")
        .env("RUST_LOG", "warn")
        .output()
        .expect("onyx runs")
}

#[test]
fn a_headless_screenshot_matches_the_showcase_reference() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("shot.png");
    let out = showcase_screenshot(false, &png);
    assert_exit(&out, 0);
    let image = onyx_render::image::open(&png).unwrap().to_rgba8();
    onyx_tests::assert_golden("showcase", &image);
}

#[test]
fn a_windowed_run_draws_the_scene_and_screenshots_it() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("window.png");
    let out = showcase_screenshot(true, &png);
    assert_exit(&out, 0);
    assert!(
        stderr(&out).is_empty() || !stderr(&out).contains("rendering disabled"),
        "{}",
        stderr(&out)
    );
    let image = onyx_render::image::open(&png).unwrap().to_rgba8();
    assert_eq!(image.dimensions(), (320, 200));
    // The window's renderer uses MSAA, the reference does not: compare on average.
    let reference =
        onyx_render::image::open(Path::new(env!("CARGO_MANIFEST_DIR")).join("golden/showcase.png"))
            .unwrap()
            .to_rgba8();
    let total: u64 = image
        .as_raw()
        .iter()
        .zip(reference.as_raw())
        .map(|(a, b)| u64::from(a.abs_diff(*b)))
        .sum();
    let mean = total as f64 / image.as_raw().len() as f64;
    assert!(
        mean < 4.0,
        "the windowed screenshot differs from the reference by {mean:.2}/255 on average"
    );
}

#[test]
fn physics_preset_comes_from_the_scene_and_the_command_line_wins() {
    let dir = tempfile::tempdir().unwrap();
    let dump_path = dir.path().join("state.json");
    let dump = dump_path.to_str().unwrap();
    let scene =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/scenes/physics/bounce_ladder.ron");
    let scene = scene.to_str().unwrap();
    let fixed_delta = |args: &[&str]| {
        let mut all = vec!["run", "--headless", "--frames", "3", "--scene", scene];
        all.extend_from_slice(args);
        all.extend_from_slice(&["--dump-state", dump]);
        let out = onyx(&all);
        assert_exit(&out, 0);
        let state = read_json(&dump_path);
        state["time"]["fixed_delta"].as_f64().unwrap()
    };
    // The scene asks for balanced (60 Hz); the command line's preset and rate win.
    assert!((fixed_delta(&[]) - 1.0 / 60.0).abs() < 1e-6);
    assert!((fixed_delta(&["--physics", "precise"]) - 1.0 / 120.0).abs() < 1e-6);
    assert!((fixed_delta(&["--physics", "fast", "--fixed-hz", "50"]) - 1.0 / 50.0).abs() < 1e-6);

    let out = onyx(&["run", "--headless", "--frames", "1", "--physics", "turbo"]);
    assert_exit(&out, 2);
    assert!(
        stderr(&out).contains("unknown physics preset \"turbo\""),
        "{}",
        stderr(&out)
    );
}

#[test]
fn a_scene_with_a_hierarchy_dumps_each_parent_and_world_pose() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("rig.ron");
    std::fs::write(
        &scene,
        r#"(version: 2, entities: [
            (id: Some(1), name: Some("base"), transform: Some((translation: (0.0, 1.0, 0.0), rotation: (0.0, 0.0, 0.38268343, 0.9238795)))),
            (name: Some("tip"), parent: Some(1), transform: Some((translation: (2.0, 0.0, 0.0), scale: (0.5, 0.5, 0.5)))),
        ])"#,
    )
    .unwrap();
    let dump_path = dir.path().join("dump.json");
    let out = onyx(&[
        "run",
        "--headless",
        "--frames",
        "2",
        "--scene",
        scene.to_str().unwrap(),
        "--dump-state",
        dump_path.to_str().unwrap(),
    ]);
    assert_exit(&out, 0);
    let dump = read_json(&dump_path);
    let base = entity(&dump, "base");
    let tip = entity(&dump, "tip");
    assert_eq!(tip["components"]["Parent"], base["id"]);
    assert!(base["components"].get("Parent").is_none());
    // 45° about Z: the tip's 2 m along local X lands at (√2, 1 + √2, 0), scaled 0.5.
    let global = &tip["components"]["GlobalTransform"];
    let t: Vec<f64> = serde_json::from_value(global["translation"].clone()).unwrap();
    let s: Vec<f64> = serde_json::from_value(global["scale"].clone()).unwrap();
    let r: Vec<f64> = serde_json::from_value(global["rotation"].clone()).unwrap();
    let root2 = std::f64::consts::SQRT_2;
    for (got, want) in t.iter().zip([root2, 1.0 + root2, 0.0]) {
        assert!((got - want).abs() < 1e-5, "translation {t:?}");
    }
    for got in &s {
        assert!((got - 0.5).abs() < 1e-5, "scale {s:?}");
    }
    for (got, want) in r.iter().zip([0.0, 0.0, 0.38268343, 0.9238795]) {
        assert!((got - want).abs() < 1e-5, "rotation {r:?}");
    }
    assert_eq!(
        tip["components"]["Transform"]["translation"],
        serde_json::json!([2.0, 0.0, 0.0]),
        "the local transform is what the file says"
    );
}

/// A preset on the command line replaces the scene's step rate and substeps only: the scene's
/// moon gravity and its own speed cap stay, and hitting that cap is said once, not per step.
#[test]
fn a_command_line_preset_keeps_the_scenes_other_physics_settings() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("moon.ron");
    std::fs::write(
        &scene,
        r#"(version: 1, physics: Some((preset: Fast, substeps: Some(3), gravity: Some((0.0, -1.62, 0.0)), max_angular_speed: Some(50.0))),
        entities: [
            (name: Some("ball"), transform: Some((translation: (0.0, 5.0, 0.0))),
             rigid_body: Some((kind: Dynamic)), collider: Some((shape: Sphere(radius: 0.5)))),
            (name: Some("top"), transform: Some((translation: (40.0, 5.0, 0.0))),
             rigid_body: Some((kind: Dynamic, angular_velocity: (0.0, 80.0, 0.0), gravity_scale: 0.0)),
             collider: Some((shape: Sphere(radius: 0.5)))),
        ])"#,
    )
    .unwrap();
    let dump_path = dir.path().join("dump.json");
    // One simulated second at precise (120 Hz): y = 5 - g t² / 2 under the scene's gravity.
    let out = onyx(&[
        "run",
        "--headless",
        "--frames",
        "120",
        "--physics",
        "precise",
        "--scene",
        scene.to_str().unwrap(),
        "--dump-state",
        dump_path.to_str().unwrap(),
    ]);
    assert_exit(&out, 0);
    let dump = read_json(&dump_path);
    assert!((dump["time"]["fixed_delta"].as_f64().unwrap() - 1.0 / 120.0).abs() < 1e-6);
    let y = entity(&dump, "ball")["components"]["Transform"]["translation"][1]
        .as_f64()
        .unwrap();
    let expected = 5.0 - 0.5 * 1.62;
    assert!(
        (y - expected).abs() < 0.02,
        "y = {y}, expected {expected} (moon gravity kept)"
    );
    let spin = entity(&dump, "top")["components"]["RigidBody"]["angular_velocity"][1]
        .as_f64()
        .unwrap();
    assert!(spin <= 50.0 + 1e-3, "spin {spin} above the scene's cap");
    let log = stderr(&out);
    let said = log.matches("spin cap of 50 rad/s").count();
    assert_eq!(said, 1, "the cap is reported once, not per step:\n{log}");
}
