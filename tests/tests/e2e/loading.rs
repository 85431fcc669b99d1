//! Loading real plugin libraries from disk, and every way a file can fail to be a plugin.

use onyx_plugin_api::{glam::Quat, Transform};
use onyx_runtime::plugins::PluginSearchPath;
use onyx_runtime::{HeadlessHost, HostConfig, PluginLoadError, PluginStatus};
use onyx_tests::{plugin_library, target_dir};

/// The plugins' component types as the tests see them: through their serialized form, as
/// any other program would (a test binary links at most one plugin rlib).
#[derive(serde::Deserialize)]
struct Stats {
    attach: u32,
    init: u32,
    fixed_updates: u64,
    updates: u64,
}

#[derive(serde::Deserialize)]
struct Spin {
    speed: f32,
}

/// A one-line, actionable message: no abi_stable type dump.
fn assert_one_sentence(message: &str) {
    assert!(!message.contains('\n'), "message spans lines: {message}");
    assert!(
        message.len() < 400,
        "message is {} chars: {message}",
        message.len()
    );
}

#[test]
fn hello_and_spinner_load_from_disk_and_run_side_by_side() {
    let mut host = HeadlessHost::new();
    assert_eq!(
        host.load_plugin_file(&plugin_library("hello")).unwrap(),
        "hello"
    );
    assert_eq!(
        host.load_plugin_file(&plugin_library("spinner")).unwrap(),
        "spinner"
    );
    host.step(30);

    // Two libraries, two distinct root modules (abi_stable's `load_from_file` would cache one).
    let dump = host.dump_state();
    let hello = dump["entities"]
        .as_array()
        .unwrap()
        .iter()
        .find(|e| e["name"] == "hello")
        .expect("hello spawned its entity");
    let stats: Stats = serde_json::from_value(hello["components"]["hello.stats"].clone()).unwrap();
    assert_eq!((stats.attach, stats.init), (1, 1));
    assert_eq!(stats.updates, 30);
    assert_eq!(stats.fixed_updates, 30, "one fixed step per 1/60 s frame");

    // spinner: 8 entities, each turned by speed × 30 steps × 1/60 s about Y.
    let spinning = {
        let mut q = host
            .world()
            .query::<&onyx_runtime::world::PluginComponents>();
        q.iter()
            .filter(|p| p.0.contains_key("spinner.spin"))
            .count()
    };
    assert_eq!(spinning, 8);
    for i in 0..8 {
        let (_, t) = host.find::<Transform>(&format!("spinner {i}")).unwrap();
        let speed = 1.0 + i as f32 * 0.25;
        let expected = Quat::from_rotation_y(speed * 30.0 / 60.0);
        assert!(
            t.rotation.angle_between(expected) < 1e-3,
            "spinner {i}: rotation {:?}, expected {:?}",
            t.rotation,
            expected
        );
    }
    let (e, _) = host.find::<Transform>("spinner 3").unwrap();
    let stored = host
        .get::<onyx_runtime::world::PluginComponents>(e)
        .unwrap();
    let spin: Spin = serde_json::from_slice(&stored.0["spinner.spin"].bytes).unwrap();
    assert_eq!(spin.speed, 1.75);
}

#[test]
fn a_plugin_name_is_found_in_the_search_path() {
    let config = HostConfig {
        search_path: PluginSearchPath::new(vec![target_dir()]),
        ..Default::default()
    };
    let mut host = HeadlessHost::with_config(config);
    assert_eq!(host.load_plugin("hello").unwrap(), "hello");
    assert_eq!(host.plugin_status("hello"), Some(&PluginStatus::Running));
}

#[test]
fn an_unknown_name_lists_where_it_looked() {
    let dir = tempfile::tempdir().unwrap();
    let config = HostConfig {
        search_path: PluginSearchPath::new(vec![dir.path().to_path_buf()]),
        ..Default::default()
    };
    let mut host = HeadlessHost::with_config(config);
    let error = host.load_plugin("no_such_plugin").unwrap_err();
    assert!(
        matches!(error, PluginLoadError::NotFound { .. }),
        "{error:?}"
    );
    let message = error.to_string();
    assert!(
        message.contains("no_such_plugin") && message.contains(&dir.path().display().to_string()),
        "{message}"
    );
    assert!(message.contains("ONYX_PLUGIN_PATH"), "{message}");
    assert_one_sentence(&message);
}

#[test]
fn a_missing_path_is_named() {
    let mut host = HeadlessHost::new();
    let error = host.load_plugin("./nowhere/libghost.so").unwrap_err();
    assert!(
        matches!(error, PluginLoadError::MissingFile { .. }),
        "{error:?}"
    );
    assert!(error.to_string().contains("nowhere/libghost.so"), "{error}");
    assert!(error.to_string().contains("does not exist"), "{error}");
}

#[test]
fn a_file_that_is_not_a_shared_library_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("libfake.so");
    std::fs::write(&path, b"this is a text file, not an ELF image").unwrap();
    let mut host = HeadlessHost::new();
    let error = host.load_plugin_file(&path).unwrap_err();
    assert!(
        matches!(error, PluginLoadError::NotALibrary { .. }),
        "{error:?}"
    );
    let message = error.to_string();
    assert!(
        message.contains("libfake.so") && message.contains("cdylib"),
        "{message}"
    );
    assert_one_sentence(&message);
}

#[test]
fn a_library_without_the_onyx_root_module_is_refused() {
    let path = plugin_library("fixture-not-a-plugin");
    let mut host = HeadlessHost::new();
    let error = host.load_plugin_file(&path).unwrap_err();
    assert!(
        matches!(error, PluginLoadError::NotAPlugin { .. }),
        "{error:?}"
    );
    let message = error.to_string();
    assert!(
        message.contains("export_plugin!") && message.contains("fixture_not_a_plugin"),
        "{message}"
    );
    assert_one_sentence(&message);
}

#[test]
fn a_plugin_built_against_an_older_api_is_refused_with_both_versions() {
    let path = plugin_library("fixture-old-api");
    let mut host = HeadlessHost::new();
    let error = host.load_plugin_file(&path).unwrap_err();
    let PluginLoadError::IncompatibleApi {
        plugin,
        built_against,
        host: ours,
        ..
    } = &error
    else {
        panic!("expected IncompatibleApi, got {error:?}");
    };
    assert_eq!(
        (plugin.as_str(), built_against.as_str()),
        ("fixture_old_api", "0.0.9")
    );
    assert_eq!(ours, onyx_plugin_api::host::API_VERSION);
    let message = error.to_string();
    assert!(
        message.starts_with(&format!(
            "plugin `fixture_old_api` was built against onyx-plugin-api 0.0.9, this host speaks {ours}: rebuild it"
        )),
        "{message}"
    );
    assert_one_sentence(&message);
}

#[test]
fn a_plugin_with_a_different_layout_is_refused_without_a_type_dump() {
    let path = plugin_library("fixture-bad-layout");
    let mut host = HeadlessHost::new();
    let error = host.load_plugin_file(&path).unwrap_err();
    let PluginLoadError::IncompatibleLayout { details, .. } = &error else {
        panic!("expected IncompatibleLayout, got {error:?}");
    };
    assert!(
        !details.is_empty(),
        "abi_stable's report is kept for the debug log"
    );
    let message = error.to_string();
    assert!(
        message.contains("fixture_bad_layout") && message.contains("rebuild"),
        "{message}"
    );
    assert_one_sentence(&message);
}

#[test]
fn loading_the_same_plugin_twice_is_refused_and_the_first_keeps_running() {
    let mut host = HeadlessHost::new();
    host.load_plugin_file(&plugin_library("hello")).unwrap();
    let error = host.load_plugin_file(&plugin_library("hello")).unwrap_err();
    assert!(
        matches!(error, PluginLoadError::AlreadyLoaded { .. }),
        "{error:?}"
    );
    host.step(2);
    assert_eq!(host.plugin_status("hello"), Some(&PluginStatus::Running));
}

#[test]
fn the_host_keeps_running_after_every_load_failure() {
    let dir = tempfile::tempdir().unwrap();
    let fake = dir.path().join("libfake.so");
    std::fs::write(&fake, b"nope").unwrap();
    let journal = onyx_tests::journal();
    let mut host = HeadlessHost::new();
    host.add_plugin("recorder", onyx_tests::Recorder::new("rec", &journal))
        .unwrap();
    for bad in [
        fake,
        dir.path().join("libmissing.so"),
        plugin_library("fixture-not-a-plugin"),
        plugin_library("fixture-old-api"),
        plugin_library("fixture-bad-layout"),
    ] {
        assert!(
            host.load_plugin_file(&bad).is_err(),
            "{} loaded",
            bad.display()
        );
    }
    host.load_plugin_file(&plugin_library("spinner")).unwrap();
    assert_eq!(host.step(10), 10);
    // Each failure was also raised as a platform event, which plugins received.
    let errors = onyx_tests::entries(&journal)
        .iter()
        .filter(|e| e.starts_with("rec.on_event:Platform(Error"))
        .count();
    assert_eq!(errors, 5);
}

#[test]
fn every_load_opens_a_fresh_copy_of_the_file() {
    let mut a = HeadlessHost::new();
    let mut b = HeadlessHost::new();
    a.load_plugin_file(&plugin_library("spinner")).unwrap();
    b.load_plugin_file(&plugin_library("spinner")).unwrap();
    let origin = |h: &HeadlessHost| match h.host().plugin("spinner").unwrap().origin() {
        onyx_runtime::plugins::PluginOrigin::Library { loaded_from, .. } => loaded_from.clone(),
        other => panic!("{other:?}"),
    };
    assert_ne!(origin(&a), origin(&b), "two loads share an image");
    // Separate images keep separate plugin state.
    a.step(5);
    b.step(2);
    assert_eq!(a.host().time().ticks, 5);
}
