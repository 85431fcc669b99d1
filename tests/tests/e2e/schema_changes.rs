//! Hot reload when the state type changes between builds, through real libraries: the
//! `fixture_schema` builds (`tests/fixtures/schema/`) differ only in the state they carry.
//! What serde can map is kept; anything else refuses the swap with one sentence naming the
//! plugin and what did not decode, and the running build goes on exactly as it was.

use std::path::PathBuf;

use onyx_plugin_api::Name;
use onyx_runtime::plugins::plugin_search::library_file_name;
use onyx_runtime::world::PluginComponents;
use onyx_runtime::{HeadlessHost, PluginStatus, ReloadError};
use onyx_tests::plugin_library;
use serde_json::{json, Value};

const NAME: &str = "fixture_schema";

/// `{build, state}` as the running build last published it.
fn published(host: &HeadlessHost) -> (String, Value) {
    let (e, _) = host
        .find::<Name>("schema")
        .expect("the plugin made its entity");
    let blobs = host.get::<PluginComponents>(e).expect("it published");
    let value: Value =
        serde_json::from_slice(&blobs.0["fixture_schema.published"].bytes).expect("JSON");
    (
        value["build"].as_str().unwrap_or_default().to_owned(),
        value["state"].clone(),
    )
}

/// A host running build v1 for 5 frames from a file in a temp dir (the file later swapped).
fn running_v1() -> (HeadlessHost, tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(library_file_name(NAME));
    std::fs::copy(plugin_library("fixture-schema-v1"), &path).unwrap();
    let mut host = HeadlessHost::new();
    assert_eq!(host.load_plugin_file(&path).unwrap(), NAME);
    host.step(5);
    let (build, state) = published(&host);
    assert_eq!(build, "v1");
    assert_eq!(state, json!({"count": 5, "speed": 1.5, "label": "v1"}));
    (host, dir, path)
}

/// Puts build `variant` in place of the running file and swaps to it.
fn swap_to(host: &mut HeadlessHost, path: &PathBuf, variant: &str) -> Result<(), ReloadError> {
    let staging = path.with_extension("staging");
    std::fs::copy(
        plugin_library(&format!("fixture-schema-{variant}")),
        &staging,
    )
    .unwrap();
    std::fs::rename(&staging, path).unwrap();
    host.host_mut().reload_plugin(NAME)
}

/// Swaps to `variant` and steps 2 frames; the published state after them.
fn kept(variant: &str) -> Value {
    let (mut host, _dir, path) = running_v1();
    swap_to(&mut host, &path, variant).unwrap_or_else(|e| panic!("{variant}: {e}"));
    host.step(2);
    let (build, state) = published(&host);
    assert_eq!(build, variant);
    assert_eq!(host.host().plugin(NAME).unwrap().reloads(), 1);
    state
}

#[test]
fn a_field_added_with_a_default_starts_at_it_and_the_rest_is_kept() {
    // 5 v1 frames, then 2 of the new build (which adds 10 to `bonus` each frame).
    assert_eq!(
        kept("added"),
        json!({"count": 7, "speed": 1.5, "label": "v1", "bonus": 20})
    );
}

#[test]
fn a_field_removed_is_dropped_and_the_rest_is_kept() {
    assert_eq!(kept("removed"), json!({"count": 7, "speed": 1.5}));
}

#[test]
fn a_field_renamed_with_an_alias_is_kept() {
    assert_eq!(
        kept("renamed"),
        json!({"count": 7, "velocity": 1.5, "label": "v1"})
    );
}

#[test]
fn a_replaced_state_type_is_kept_through_its_migration() {
    // v1's unversioned state is version 0 of `Progress`, migrated to version 1.
    assert_eq!(kept("replaced"), json!({"ticks": 7, "pace_tenths": 15}));
}

/// A refused swap: one sentence, and v1 runs on exactly as before (same image, same state,
/// counting on), with no trace of the new build.
fn assert_refused(host: &mut HeadlessHost, error: ReloadError, what: &[&str]) {
    let sentence = error.to_string();
    assert!(
        matches!(error, ReloadError::StateRefused { .. }),
        "{error:?}"
    );
    assert!(
        sentence.starts_with("plugin `fixture_schema` was not reloaded: "),
        "{sentence}"
    );
    for needle in what {
        assert!(sentence.contains(needle), "`{needle}` not in: {sentence}");
    }
    assert_eq!(sentence.lines().count(), 1, "{sentence}");
    assert_eq!(host.plugin_status(NAME), Some(&PluginStatus::Running));
    assert_eq!(host.host().plugin(NAME).unwrap().reloads(), 0);
    assert!(
        host.host().incidents().is_empty(),
        "{:?}",
        host.host().incidents()
    );
    host.step(3);
    let (build, state) = published(host);
    assert_eq!(build, "v1", "the old build stopped");
    assert_eq!(state["count"], 8, "the old build's state changed: {state}");
}

#[test]
fn a_field_whose_type_changed_refuses_the_swap_naming_the_field() {
    let (mut host, _dir, path) = running_v1();
    let error = swap_to(&mut host, &path, "retyped").unwrap_err();
    assert_refused(
        &mut host,
        error,
        &[
            "fixture_schema_retyped::State",
            "at `count`",
            "invalid type: integer `5`, expected a string",
        ],
    );
}

#[test]
fn an_older_build_refuses_a_newer_builds_state_and_the_newer_one_keeps_running() {
    let (mut host, _dir, path) = running_v1();
    swap_to(&mut host, &path, "replaced").unwrap();
    host.step(1);
    // Back to v1: its plain `decode` does not know the versioned state.
    let error = swap_to(&mut host, &path, "v1").unwrap_err();
    let sentence = error.to_string();
    assert!(
        matches!(error, ReloadError::StateRefused { .. })
            && sentence.contains("fixture_schema_v1::State")
            && sentence.contains("missing field `count`"),
        "{sentence}"
    );
    host.step(2);
    let (build, state) = published(&host);
    assert_eq!(build, "replaced");
    assert_eq!(state, json!({"ticks": 8, "pace_tenths": 15}));
    assert_eq!(host.plugin_status(NAME), Some(&PluginStatus::Running));
}
