//! The tool services the editor is built on (world introspection, scenes, plugins,
//! diagnostics, console, play mode, scripts, viewport), used by a real cdylib plugin loaded
//! from disk (`tests/fixtures/services`), which writes what it saw to `report.json`.

use std::path::Path;

use onyx_plugin_api::{Name, Transform};
use onyx_runtime::world::PluginComponents;
use onyx_runtime::{HeadlessHost, HostConfig};
use onyx_tests::plugin_library;
use serde_json::Value;

const SERVICES: &str = "fixture_services";

/// A host running the services fixture with `probe`, for `frames` frames; returns the host,
/// the report and the folder (kept alive).
fn run_probe(probe: &str, frames: u32) -> (HeadlessHost, Value, tempfile::TempDir) {
    let dir = tempfile::tempdir().unwrap();
    let config = HostConfig::default()
        .setting(SERVICES, "probe", probe)
        .setting(SERVICES, "dir", dir.path().display().to_string());
    let mut host = HeadlessHost::with_config(config);
    host.load_plugin_file(&plugin_library("fixture-services"))
        .unwrap();
    host.step(frames);
    let report = read_report(dir.path());
    (host, report, dir)
}

fn read_report(dir: &Path) -> Value {
    let text =
        std::fs::read_to_string(dir.join("report.json")).expect("the fixture wrote a report");
    serde_json::from_str(&text).unwrap()
}

fn no_error(report: &Value, key: &str) {
    assert_eq!(report[key], Value::Null, "`{key}` failed: {}", report[key]);
}

fn error_of<'a>(report: &'a Value, key: &str) -> &'a str {
    report[key]
        .as_str()
        .unwrap_or_else(|| panic!("`{key}` should have failed, got {}", report[key]))
}

#[test]
fn a_plugin_lists_entities_and_reads_and_edits_their_components() {
    let (host, r, _dir) = run_probe("introspect", 1);
    let ids: Vec<u64> = serde_json::from_value(r["ids"].clone()).unwrap();
    let list: Vec<(u64, String)> = serde_json::from_value(r["list"].clone()).unwrap();
    assert_eq!(
        list,
        vec![
            (ids[0], "alpha".to_owned()),
            (ids[1], "beta".to_owned()),
            (ids[2], String::new())
        ]
    );
    assert_eq!(
        r["component_names"],
        serde_json::json!(["Name", "Transform", "fixture.tag"]),
        "built-ins in list order, then plugin components"
    );
    assert_eq!(r["name_value"], "alpha");
    assert_eq!(r["tag_value"], serde_json::json!({"label": "hi"}));
    no_error(&r, "set_ok");
    assert_eq!(r["after_set"], serde_json::json!([5.0, 6.0, 7.0]));
    let inf = error_of(&r, "set_inf");
    assert!(
        inf.contains("NaN or infinity") && inf.contains("`scale`") && inf.contains("Transform"),
        "{inf}"
    );
    let camera = error_of(&r, "set_bad_camera");
    assert!(
        camera.contains("`near`") && camera.contains("-1") && camera.contains("Camera"),
        "the error names the component, the field and the value: {camera}"
    );
    assert_eq!(
        r["after_bad"], r["after_set"],
        "a refused write changed the world"
    );
    assert_eq!(r["has_camera"], false);
    no_error(&r, "set_tag");
    assert_eq!(r["tag"], "edited");
    no_error(&r, "add_collider");
    assert_eq!(r["parent_default"], false, "a Parent needs an entity");
    assert_eq!(r["has_collider"], true);
    no_error(&r, "remove_name");
    assert_eq!(r["has_name"], false);
    no_error(&r, "remove_tag");
    assert_eq!(r["has_tag"], false);
    assert!(error_of(&r, "remove_tag_again").contains("has no `fixture.tag`"));
    assert!(error_of(&r, "components_of_missing").contains("does not exist"));
    assert_eq!(r["big_len"], 10_003);
    assert_eq!(r["big_last"], "n9999");
    assert!(host.find::<Name>("n9999").is_some());
}

#[test]
fn a_plugin_saves_opens_and_clears_scenes_and_a_bad_file_leaves_the_world_alone() {
    let (host, r, dir) = run_probe("scene", 2);
    assert_eq!(r["path_before"], Value::Null);
    no_error(&r, "save");
    let saved = dir.path().join("a.scene.ron").display().to_string();
    assert_eq!(r["path_after_save"], saved.as_str());
    no_error(&r, "new");
    assert_eq!(r["after_new"], 0);
    assert_eq!(r["path_after_new"], Value::Null);
    no_error(&r, "open");
    assert_eq!(r["after_open"], serde_json::json!(["saved"]));
    let bad = error_of(&r, "open_bad");
    assert!(
        bad.contains("bad.scene.ron") && bad.contains("line"),
        "{bad}"
    );
    assert!(error_of(&r, "open_missing").contains("missing.ron"));
    assert_eq!(r["after_bad"], serde_json::json!(["saved"]));
    assert_eq!(
        r["script_after_open"], "Rotator",
        "the Script survives save and open"
    );
    let (_, t) = host.find::<Transform>("saved").unwrap();
    assert_eq!(t.translation.y, 4.0);
}

#[test]
fn the_plugin_list_shows_a_faulted_plugin_with_its_error_and_diagnostics_time_each_plugin() {
    let dir = tempfile::tempdir().unwrap();
    let config = HostConfig::default()
        .setting(SERVICES, "probe", "plugins")
        .setting(SERVICES, "dir", dir.path().display().to_string())
        .setting("fixture_faulty", "panic_in", "on_update");
    let mut host = HeadlessHost::with_config(config);
    host.load_plugin_file(&plugin_library("fixture-services"))
        .unwrap();
    host.load_plugin_file(&plugin_library("fixture-faulty"))
        .unwrap();
    host.step(3);
    let r = read_report(dir.path());
    let plugins = r["plugins"].as_array().unwrap();
    assert_eq!(plugins.len(), 2);
    assert_eq!(plugins[0]["name"], SERVICES);
    assert_eq!(plugins[0]["state"], "Running");
    assert!(plugins[0]["path"]
        .as_str()
        .is_some_and(|p| p.contains("fixture_services")));
    let faulted = &plugins[1]["state"]["Faulted"];
    assert_eq!(faulted["stage"], "on_update");
    assert!(faulted["message"]
        .as_str()
        .unwrap()
        .contains("fixture_faulty panics in on_update"));

    let d = &r["diagnostics"];
    assert_eq!(d["fixed_steps"], 1);
    assert!(d["frame_ms"].as_f64().unwrap() > 0.0);
    let timings = d["plugins"].as_array().unwrap();
    assert_eq!(timings[0]["plugin"], SERVICES);
    let stages: Vec<&str> = timings[0]["stages"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["stage"].as_str().unwrap())
        .collect();
    assert!(
        stages.contains(&"on_update") && stages.contains(&"on_fixed_update"),
        "{stages:?}"
    );
    // The host side sees the same figures.
    assert_eq!(host.host().diagnostics().fixed_steps, 1);
}

#[test]
fn the_console_keeps_plugin_and_host_lines_and_reads_them_incrementally() {
    let (_host, r, _dir) = run_probe("console", 2);
    let lines = r["lines"].as_array().unwrap();
    let marker = lines
        .iter()
        .find(|l| l["message"] == "console marker two")
        .expect("the plugin's own line is in the console");
    assert_eq!(marker["source"], SERVICES);
    assert_eq!(marker["level"], "WARN");
    let physics = lines
        .iter()
        .find(|l| {
            l["message"]
                .as_str()
                .unwrap()
                .contains("does/not/exist.obj")
        })
        .expect("the physics error is in the console");
    assert_eq!(physics["level"], "ERROR");
    assert!(
        physics["message"]
            .as_str()
            .unwrap()
            .contains("subsystem=physics"),
        "{physics}"
    );
    let since = r["seq"].as_u64().unwrap();
    assert!(lines.iter().all(|l| l["seq"].as_u64().unwrap() > since));
    assert!(
        lines.iter().all(|l| l["message"] != "console marker one"),
        "lines before `seq` were returned again"
    );
    // Host lines (loading the plugin) are there too.
    let all = onyx_runtime::console::console_log().since(0);
    assert!(all.iter().any(
        |l| l.message.contains("loaded plugin library") && l.source.starts_with("onyx_runtime")
    ));
}

#[test]
fn stop_puts_the_world_back_as_it_was_at_play_and_edit_mode_runs_no_physics() {
    let (host, r, _dir) = run_probe("play", 25);
    assert_eq!(r["mode_start"], "Playing");
    assert_eq!(r["mode_after_stop"], "Edit");
    assert_eq!(r["y_edit"], 10.0, "a body fell in Edit mode");
    assert_eq!(r["mode_play"], "Playing");
    let played = r["y_played"].as_f64().unwrap();
    assert!(
        played < 9.9,
        "the body did not fall while playing: y = {played}"
    );
    assert_eq!(r["mode_pause"], "Paused");
    let paused = r["y_paused"].as_f64().unwrap();
    let stepped = r["y_stepped"].as_f64().unwrap();
    assert!(
        stepped < paused,
        "a step did not move the body: {paused} → {stepped}"
    );
    assert_eq!(r["mode_stop"], "Edit");
    assert_eq!(r["y_restored"], 10.0);
    assert_eq!(r["v_restored"], serde_json::json!([0.0, 0.0, 0.0]));
    assert_eq!(
        r["tag_restored"], "before",
        "plugin components come back too"
    );
    assert_eq!(
        r["names_restored"],
        serde_json::json!(["ball"]),
        "an entity made while playing survived Stop"
    );
    assert_eq!(host.host().play_mode(), onyx_plugin_api::PlayMode::Edit);
}

#[test]
fn a_registered_script_runs_on_its_entity_until_removed() {
    let (host, r, _dir) = run_probe("scripts", 13);
    let registered = r["registered"].as_array().unwrap();
    assert_eq!(registered[0]["name"], "Rotator");
    assert_eq!(registered[0]["plugin"], SERVICES);
    assert_eq!(registered[0]["default_params"]["speed"], 0.5);
    assert!(
        error_of(&r, "add_broken_script").contains("could not decode `onyx.Script`"),
        "{}",
        r["add_broken_script"]
    );
    no_error(&r, "add_script");
    assert_eq!(r["added_script"]["name"], "Rotator");
    assert_eq!(r["added_script"]["params"]["speed"], 0.5);
    assert!(error_of(&r, "duplicate").contains("non-empty name"));
    // Spawned in frame 1's on_update: created then updated in frames 1..=10 before frame 11
    // reads it.
    assert_eq!(r["log"]["created"], 1);
    assert_eq!(r["log"]["updates"], 10);
    let angle = r["angle"].as_f64().unwrap();
    let expected = 10.0 / 60.0; // 1 rad/s for ten frames of 1/60 s
    assert!(
        (angle - expected).abs() < 1e-4,
        "rotated {angle} rad, expected {expected}"
    );
    let (fan, _) = host.find::<Name>("fan").unwrap();
    assert_eq!(r["destroyed"], serde_json::json!([fan.to_bits()]));
    let components = host.get::<PluginComponents>(fan).unwrap();
    assert!(!components.0.contains_key("onyx.Script"));
}

#[test]
fn a_screen_ray_through_the_active_camera_picks_what_is_under_the_pixel() {
    let (_host, r, _dir) = run_probe("viewport", 2);
    let centre: ([f32; 3], [f32; 3]) = serde_json::from_value(r["centre"].clone()).unwrap();
    let (origin, direction) = centre;
    assert!(
        (origin[0]).abs() < 1e-4 && (origin[1]).abs() < 1e-4,
        "{origin:?}"
    );
    assert!(
        origin[2] < 10.0 && origin[2] > 9.0,
        "starts on the near plane: {origin:?}"
    );
    assert!(
        (direction[2] + 1.0).abs() < 1e-4,
        "looks down -Z: {direction:?}"
    );
    assert_eq!(r["outside"], false);
    assert_eq!(r["picked"], r["target"]);
    assert!(r["overrides_default"]
        .as_str()
        .unwrap()
        .contains("grid: RNone"));
    let overrides = r["overrides"].as_str().unwrap();
    assert!(
        overrides.contains("grid: RSome(false)")
            && overrides.contains("physics_debug: RSome(true)")
            && overrides.contains("Wireframe"),
        "{overrides}"
    );
}

#[test]
fn diagnostics_count_the_triangles_and_draw_calls_of_the_last_image() {
    let (mut host, _r, _dir) = run_probe("viewport", 2);
    let image = host.screenshot(64, 32).expect("offscreen rendering works");
    assert_eq!((image.width(), image.height()), (64, 32));
    let d = host.host().diagnostics().clone();
    // One cube (12 triangles) in view, grid switched off, physics lines switched on.
    assert_eq!(d.triangles, 12, "{d:?}");
    assert_eq!(d.instances, 1, "{d:?}");
    assert_eq!(
        d.draw_calls, 3,
        "the cube, the sky and the physics lines, no grid: {d:?}"
    );
    // The renderer's start-up lines (adapter, backend, driver) are in the console.
    let lines = onyx_runtime::console::console_log().since(0);
    assert!(
        lines
            .iter()
            .any(|l| l.message.contains("graphics adapter selected")
                && l.message.contains("backend=")),
        "no adapter line in the console"
    );
}

#[test]
fn the_onyx_binary_feeds_the_console_that_plugins_read() {
    let dir = tempfile::tempdir().unwrap();
    let out = std::process::Command::new(onyx_tests::onyx_binary())
        .args(["run", "--headless", "--frames", "3", "--plugin"])
        .arg(plugin_library("fixture-services"))
        .arg("--set")
        .arg(format!("{SERVICES}.probe=console"))
        .arg("--set")
        .arg(format!("{SERVICES}.dir={}", dir.path().display()))
        .env("RUST_LOG", "info")
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let r = read_report(dir.path());
    let lines = r["lines"].as_array().unwrap();
    assert!(
        lines
            .iter()
            .any(|l| l["message"] == "console marker two" && l["source"] == SERVICES),
        "{lines:?}"
    );
    // People still get the log on stderr.
    assert!(String::from_utf8_lossy(&out.stderr).contains("console marker two"));
}

/// Runs `f` with a `Ctx` on `host`'s services, as a plugin call would.
fn with_ctx<R>(host: &mut HeadlessHost, f: impl FnOnce(&mut onyx_plugin_api::Ctx<'_>) -> R) -> R {
    host.host_mut().with_services("tool", |services| {
        onyx_plugin_api::__ffi::with_ctx(services, f)
    })
}

/// A new or opened scene started a fresh hecs world, so handles began again: a handle kept
/// from before named the next scene's first entity (the editor moved the Sun with its view).
#[test]
fn a_handle_kept_across_new_and_open_names_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("two.ron");
    std::fs::write(
        &scene,
        r#"(version: 2, entities: [(name: Some("Sun")), (name: Some("Moon"))])"#,
    )
    .unwrap();
    let mut host = HeadlessHost::new();
    with_ctx(&mut host, |ctx| {
        let before = ctx.spawn(Name::new("camera")).unwrap();
        ctx.new_scene().unwrap();
        assert!(!ctx.contains(before), "New emptied the world");
        let in_new = ctx.spawn(Name::new("camera")).unwrap();
        ctx.open_scene(&scene.display().to_string()).unwrap();
        for kept in [before, in_new] {
            assert!(
                !ctx.contains(kept),
                "{kept:?} names an entity of the opened scene"
            );
            assert!(ctx.get::<Name>(kept).is_err());
        }
        assert_eq!(ctx.entity_list().len(), 2, "the scene's two entities");
    });
}

/// Clicks in the editor picked by bounding spheres (or by physics, which Edit mode does not
/// step): `pick` meets what each entity shows — meshes and colliders at world poses.
#[test]
fn pick_meets_meshes_and_colliders_at_world_poses_without_a_physics_step() {
    use onyx_plugin_api::glam::{Quat, Vec3};
    use onyx_plugin_api::{Collider, MeshId, MeshRenderer, Parent};
    let mut host = HeadlessHost::new();
    with_ctx(&mut host, |ctx| {
        let cube = ctx
            .spawn((
                Name::new("cube"),
                Transform::from_xyz(0.0, 0.0, -5.0),
                MeshRenderer::new(MeshId::CUBE),
            ))
            .unwrap();
        let ball = ctx
            .spawn((
                Name::new("ball collider"),
                Transform::from_xyz(3.0, 0.0, -5.0),
                Collider::sphere(0.5),
            ))
            .unwrap();
        let floor = ctx
            .spawn((
                Name::new("floor"),
                Transform::from_xyz(0.0, -1.0, 0.0).with_scale(Vec3::new(10.0, 1.0, 10.0)),
                MeshRenderer::new(MeshId::PLANE),
                Collider::plane(),
            ))
            .unwrap();
        // A child one metre along its parent's X; the parent turned 90° about Y puts it at
        // (0, 3, -6).
        let arm = ctx
            .spawn((
                Name::new("arm"),
                Transform::from_xyz(0.0, 3.0, -5.0)
                    .with_rotation(Quat::from_rotation_y(std::f32::consts::FRAC_PI_2)),
            ))
            .unwrap();
        let hand = ctx
            .spawn((
                Name::new("hand"),
                Transform::from_xyz(1.0, 0.0, 0.0),
                MeshRenderer::new(MeshId::SPHERE),
                Parent(arm),
            ))
            .unwrap();

        let hit = ctx.pick(Vec3::ZERO, Vec3::NEG_Z, 100.0).expect("the cube");
        assert_eq!(hit.entity, cube);
        assert!((hit.distance - 4.5).abs() < 1e-4, "{hit:?}");
        assert!((hit.normal - Vec3::Z).length() < 1e-4, "{hit:?}");
        let hit = ctx.pick(Vec3::new(3.0, 0.0, 0.0), Vec3::NEG_Z, 100.0);
        assert_eq!(hit.map(|h| h.entity), Some(ball), "a collider alone");
        let hit = ctx
            .pick(Vec3::new(0.0, 3.0, 0.0), Vec3::NEG_Z, 100.0)
            .expect("the hand");
        assert_eq!(hit.entity, hand);
        assert!(
            (hit.distance - 5.5).abs() < 1e-4,
            "at its world pose: {hit:?}"
        );
        let down = Vec3::new(0.0, -1.0, -1.0).normalize();
        let hit = ctx.pick(Vec3::ZERO, down, 100.0).expect("the floor");
        assert_eq!(hit.entity, floor);
        assert!((hit.distance - 2f32.sqrt()).abs() < 1e-3, "{hit:?}");
        // The floor's half-space collider does not reach past its mesh, nor up into the sky.
        assert!(ctx.pick(Vec3::ZERO, Vec3::Y, 100.0).is_none(), "the sky");
        assert!(
            ctx.pick(Vec3::new(0.0, 0.0, 20.0), down, 100.0).is_none(),
            "past the floor"
        );
        assert!(
            ctx.pick(Vec3::ZERO, Vec3::NEG_Z, 4.0).is_none(),
            "beyond the distance"
        );

        let cube_box = ctx.local_bounds(cube).expect("a cube has bounds");
        assert_eq!(
            (cube_box.min, cube_box.max),
            (Vec3::splat(-0.5), Vec3::splat(0.5))
        );
        let ball_box = ctx.local_bounds(ball).expect("a collider has bounds");
        assert_eq!(ball_box.max, Vec3::splat(0.5));
        assert!(ctx.local_bounds(arm).is_none(), "nothing shown, no bounds");
    });
}
