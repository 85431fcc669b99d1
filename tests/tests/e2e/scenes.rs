//! Scene files: round trips, errors with line and column, atomic saves.

use std::path::{Path, PathBuf};

use onyx_plugin_api::glam::Quat;
use onyx_plugin_api::{Name, Transform};
use onyx_runtime::scene::{read_scene, SceneError};
use onyx_runtime::HeadlessHost;
use onyx_tests::plugin_library;

fn demo_scene() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/scenes/demo.ron")
}

fn entity_count(host: &HeadlessHost) -> usize {
    host.world().iter().count()
}

#[test]
fn the_demo_scene_loads_and_spinner_spins_its_entities() {
    let mut host = HeadlessHost::new();
    assert_eq!(host.load_scene(&demo_scene()).unwrap(), 4);
    host.load_plugin_file(&plugin_library("spinner")).unwrap();
    host.step(60);
    assert_eq!(
        entity_count(&host),
        4,
        "spinner spawned none: the scene had spinners"
    );
    let (_, fast) = host.find::<Transform>("fast").unwrap();
    let expected = Quat::from_rotation_y(3.0 * 1.0);
    assert!(
        fast.rotation.angle_between(expected) < 1e-3,
        "{:?}",
        fast.rotation
    );
    assert_eq!(
        fast.scale.x, 0.5,
        "fields left out of a transform take their defaults, the rest are kept"
    );
}

#[test]
fn a_saved_scene_loads_back_identical() {
    let dir = tempfile::tempdir().unwrap();
    let mut first = HeadlessHost::new();
    first.load_scene(&demo_scene()).unwrap();
    first.load_plugin_file(&plugin_library("hello")).unwrap();
    first.step(5);
    let path = dir.path().join("saved.ron");
    first.host().save_scene(&path).unwrap();

    let mut second = HeadlessHost::new();
    second.load_scene(&path).unwrap();
    let strip = |mut dump: serde_json::Value| {
        for e in dump["entities"].as_array_mut().unwrap() {
            e.as_object_mut().unwrap().remove("id");
        }
        dump["entities"].clone()
    };
    assert_eq!(strip(first.dump_state()), strip(second.dump_state()));
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(
        text.contains("\"hello.stats\": Json("),
        "serde components stay readable:\n{text}"
    );
    assert!(
        text.contains("Raw(\"aGVsbG8=\")"),
        "raw components are base64:\n{text}"
    );
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn a_malformed_scene_reports_line_and_column_and_changes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let text = "(\n    version: 1,\n    entities: [\n        (name: Some(\"ok\")),\n        (name: Some(\"broken\"), transform: Some((translation: (1.0, oops, 0.0)))),\n    ],\n)\n";
    let path = write(dir.path(), "bad.ron", text);
    let mut host = HeadlessHost::new();
    host.load_scene(&demo_scene()).unwrap();
    let error = host.load_scene(&path).unwrap_err();
    let SceneError::Parse { line, column, .. } = &error else {
        panic!("{error:?}")
    };
    assert_eq!(*line, 5, "{error}");
    assert!(*column > 40, "{error}");
    assert!(
        error.to_string().contains("bad.ron") && error.to_string().contains("line 5"),
        "{error}"
    );
    assert_eq!(entity_count(&host), 4, "a failed load added entities");
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        text,
        "the file was touched"
    );
}

#[test]
fn scene_values_are_checked_before_anything_is_spawned() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        ("version.ron", "(version: 99, entities: [])", "format version 99"),
        ("nan.ron", "(version: 1, entities: [(name: Some(\"a\")), (transform: Some((translation: (NaN, 0.0, 0.0))))])", "entity #1: its transform `translation` holds NaN"),
        ("base64.ron", "(version: 1, entities: [(components: {\"x\": Raw(\"***\")})])", "not valid base64"),
        ("unknown.ron", "(version: 1, entities: [(nmae: Some(\"typo\"))])", "nmae"),
        ("empty.ron", "", "line 1"),
    ];
    for (file, text, expected) in cases {
        let path = write(dir.path(), file, text);
        let mut host = HeadlessHost::new();
        let error = host.load_scene(&path).unwrap_err();
        assert!(error.to_string().contains(expected), "{file}: {error}");
        assert_eq!(entity_count(&host), 0, "{file}: partial load");
    }
    let missing = HeadlessHost::new()
        .load_scene(&dir.path().join("absent.ron"))
        .unwrap_err();
    assert!(matches!(missing, SceneError::Io { .. }) && missing.to_string().contains("absent.ron"));
}

#[test]
fn saving_replaces_the_file_atomically() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.ron");
    let mut host = HeadlessHost::new();
    host.load_scene(&demo_scene()).unwrap();
    host.host().save_scene(&path).unwrap();
    let before = std::fs::read_to_string(&path).unwrap();

    // A save that cannot complete leaves the old file as it was.
    let bad = dir.path().join("no_such_dir").join("scene.ron");
    assert!(host.host().save_scene(&bad).is_err());
    assert!(!bad.exists());

    // A successful save writes a new file and renames it over the old one: the old inode is
    // never truncated, so a reader (or a crash) sees either the old or the new scene.
    #[cfg(unix)]
    let inode_before = std::os::unix::fs::MetadataExt::ino(&std::fs::metadata(&path).unwrap());
    host.host_mut().world_mut().spawn((Name::new("added"),));
    host.host().save_scene(&path).unwrap();
    #[cfg(unix)]
    {
        let inode_after = std::os::unix::fs::MetadataExt::ino(&std::fs::metadata(&path).unwrap());
        assert_ne!(inode_before, inode_after, "the file was rewritten in place");
    }
    let after = read_scene(&path).unwrap();
    assert_eq!(after.entities.len(), 5);
    assert_ne!(before, std::fs::read_to_string(&path).unwrap());
    let leftovers: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(leftovers.len(), 1, "temporary files left behind");
}

#[test]
fn a_scene_chooses_its_physics_preset_and_saves_it_back() {
    use onyx_runtime::{PhysicsPreset, ScenePhysics};
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "precise.ron",
        "(version: 1, physics: Some((preset: Precise, gravity: Some((0.0, -1.62, 0.0)))), \
         entities: [(name: Some(\"ball\"), transform: Some((translation: (0.0, 5.0, 0.0))), \
         rigid_body: Some((kind: Dynamic)), collider: Some((shape: Sphere(radius: 0.5))))])",
    );
    let mut host = HeadlessHost::new();
    host.load_scene(&path).unwrap();
    assert!((host.host_mut().clock_mut().fixed_delta() - 1.0 / 120.0).abs() < 1e-12);
    let settings = *host.host().physics().world().settings();
    assert_eq!(settings.substeps, 4);
    assert_eq!(settings.gravity.y, -1.62);

    // One simulated second at 120 Hz under lunar gravity: y = 5 - g t² / 2, up to the
    // semi-implicit Euler error of one step.
    host.set_frame_time(1.0 / 120.0);
    host.step(120);
    let (_, t) = host.find::<Transform>("ball").unwrap();
    let expected = 5.0 - 0.5 * 1.62;
    assert!(
        (t.translation.y - expected).abs() < 0.01,
        "y = {}, expected {expected}",
        t.translation.y
    );

    let saved = dir.path().join("saved.ron");
    host.host().save_scene(&saved).unwrap();
    let file = read_scene(&saved).unwrap();
    assert_eq!(
        file.physics,
        Some(ScenePhysics {
            preset: PhysicsPreset::Precise,
            gravity: Some([0.0, -1.62, 0.0]),
            ..ScenePhysics::default()
        })
    );
}

#[test]
fn a_scene_with_bad_physics_settings_is_refused_and_changes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(
        dir.path(),
        "bad.ron",
        "(version: 1, physics: Some((preset: Fast, substeps: Some(0))), \
         entities: [(name: Some(\"a\"))])",
    );
    let mut host = HeadlessHost::new();
    let error = host.load_scene(&path).unwrap_err();
    assert!(
        matches!(error, SceneError::InvalidPhysics { .. }),
        "{error}"
    );
    assert!(error.to_string().contains("physics.substeps"), "{error}");
    assert_eq!(entity_count(&host), 0);
    assert!((host.host_mut().clock_mut().fixed_delta() - 1.0 / 60.0).abs() < 1e-12);

    let unknown = write(
        dir.path(),
        "unknown.ron",
        "(version: 1, physics: Some((preset: Turbo)), entities: [])",
    );
    let error = host.load_scene(&unknown).unwrap_err();
    assert!(
        matches!(error, SceneError::Parse { line: 1, .. }),
        "{error}"
    );
}

/// A version-2 scene: children before their parents, ids that are not positions, three
/// levels, rotation and scale on the way down.
const TREE: &str = r#"(
    version: 2,
    entities: [
        (name: Some("finger"), parent: Some(7), transform: Some((translation: (0.0, 0.5, 0.0)))),
        (id: Some(40), name: Some("body"), transform: Some((translation: (1.0, 2.0, 3.0), rotation: (0.0, 0.70710677, 0.0, 0.70710677), scale: (2.0, 2.0, 2.0)))),
        (id: Some(7), name: Some("hand"), parent: Some(40), transform: Some((translation: (1.0, 0.0, 0.0)))),
        (name: Some("loose")),
    ],
)"#;

fn world_translation(host: &HeadlessHost, name: &str) -> onyx_plugin_api::glam::Vec3 {
    let (e, _) = host.find::<Name>(name).unwrap();
    host.host().world_pose(e).unwrap().translation()
}

#[test]
fn a_version_2_scene_with_a_hierarchy_loads_its_world_poses_and_saves_the_same_tree() {
    use onyx_plugin_api::glam::Vec3;
    let dir = tempfile::tempdir().unwrap();
    let path = write(dir.path(), "tree.ron", TREE);
    let mut host = HeadlessHost::new();
    assert_eq!(host.load_scene(&path).unwrap(), 4);
    host.step(1);
    // body: at (1, 2, 3), turned 90° about Y (local +X → world -Z), scaled 2.
    // hand: 1 m along body's X → 2 m along world -Z. finger: 0.5 m up → 1 m up.
    let near = |a: Vec3, b: Vec3| (a - b).length() < 1e-5;
    let hand = world_translation(&host, "hand");
    assert!(near(hand, Vec3::new(1.0, 2.0, 1.0)), "hand at {hand}");
    let finger = world_translation(&host, "finger");
    assert!(near(finger, Vec3::new(1.0, 3.0, 1.0)), "finger at {finger}");

    let saved = dir.path().join("saved.ron");
    host.host().save_scene(&saved).unwrap();
    let file = read_scene(&saved).unwrap();
    assert_eq!(file.version, onyx_runtime::scene::SCENE_FORMAT_VERSION);
    let by_name = |name: &str| {
        file.entities
            .iter()
            .find(|e| e.name.as_deref() == Some(name))
            .unwrap()
            .clone()
    };
    assert_eq!(by_name("finger").parent, by_name("hand").id);
    assert_eq!(by_name("hand").parent, by_name("body").id);
    assert!(by_name("hand").id.is_some() && by_name("body").parent.is_none());
    assert!(by_name("loose").id.is_none(), "only parents need an id");

    let mut again = HeadlessHost::new();
    again.load_scene(&saved).unwrap();
    again.step(1);
    for name in ["body", "hand", "finger"] {
        assert!(
            near(
                world_translation(&again, name),
                world_translation(&host, name)
            ),
            "{name} moved in the round trip"
        );
    }
}

#[test]
fn a_dangling_cyclic_or_repeated_parent_reference_is_refused_naming_the_entity() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            "dangling.ron",
            "(version: 2, entities: [(name: Some(\"a\")), (name: Some(\"orphan\"), parent: Some(9))])",
            "entity #1 (\"orphan\"): its parent is id 9, which no entity of the file has",
        ),
        (
            "cycle.ron",
            "(version: 2, entities: [(id: Some(1), name: Some(\"x\"), parent: Some(2)), (id: Some(2), name: Some(\"y\"), parent: Some(1))])",
            "entity #0 (\"x\"): its parent chain loops back to it",
        ),
        (
            "self.ron",
            "(version: 2, entities: [(name: Some(\"a\")), (id: Some(5), name: Some(\"me\"), parent: Some(5))])",
            "entity #1 (\"me\"): its parent chain loops back to it",
        ),
        (
            "twice.ron",
            "(version: 2, entities: [(id: Some(3), name: Some(\"first\")), (id: Some(3))])",
            "entity #1: its id 3 is already the id of entity #0",
        ),
    ];
    for (file, text, expected) in cases {
        let path = write(dir.path(), file, text);
        let mut host = HeadlessHost::new();
        let error = host.load_scene(&path).unwrap_err();
        assert!(
            matches!(error, SceneError::InvalidEntity { .. }),
            "{file}: {error:?}"
        );
        assert!(error.to_string().contains(expected), "{file}: {error}");
        assert_eq!(entity_count(&host), 0, "{file}: something spawned");
    }
}

#[test]
fn every_scene_file_in_the_repository_still_loads() {
    fn scenes(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap().flatten() {
            let path = entry.path();
            if path.is_dir() {
                scenes(&path, out);
            } else if path.extension().is_some_and(|e| e == "ron") {
                out.push(path);
            }
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = Vec::new();
    scenes(&root.join("assets/scenes"), &mut files);
    assert!(files.len() >= 10, "found only {files:?}");
    for path in files {
        let mut host =
            HeadlessHost::with_config(onyx_runtime::HostConfig::default().asset_root(root.clone()));
        let count = host
            .load_scene(&path)
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(count > 0, "{}: no entities", path.display());
        host.step(2);
        let dump = host.dump_state();
        for entity in dump["entities"].as_array().unwrap() {
            let components = &entity["components"];
            if components.get("Transform").is_some() {
                assert!(
                    components.get("GlobalTransform").is_some(),
                    "{}: {entity}",
                    path.display()
                );
            }
        }
    }
}
