//! Scene files from before colliders scaled with their entity (versions 1 and 2) keep every
//! body the size it had: read, their colliders on scaled entities are divided by the
//! entity's world scale, and the scene is version 3 from then on.

use std::path::Path;

use onyx_plugin_api::{ColliderShapeFile, RigidBody, Transform};
use onyx_runtime::scene::{parse_scene, SceneFile, SCENE_FORMAT_VERSION};
use onyx_runtime::HeadlessHost;

fn parse(text: &str) -> SceneFile {
    parse_scene(text, Path::new("test.ron")).unwrap_or_else(|e| panic!("{e}"))
}

fn shape(scene: &SceneFile, name: &str) -> (ColliderShapeFile, [f32; 3]) {
    let entity = scene
        .entities
        .iter()
        .find(|e| e.name.as_deref() == Some(name))
        .unwrap_or_else(|| panic!("no entity {name}"));
    let collider = entity
        .collider
        .clone()
        .unwrap_or_else(|| panic!("{name} has a collider"));
    (collider.shape, collider.offset)
}

const OLD: &str = r#"(version: 2, entities: [
    (name: Some("slab"), transform: Some((scale: (4.0, 0.5, 2.0))),
     collider: Some((shape: Box(half_extents: (2.0, 0.25, 1.0)), offset: (0.0, 0.5, 0.0)))),
    (id: Some(1), name: Some("big"), transform: Some((scale: (2.0, 2.0, 2.0)))),
    (name: Some("ball"), parent: Some(1), transform: Some((scale: (1.5, 1.5, 1.5))),
     collider: Some((shape: Sphere(radius: 1.5)))),
    (name: Some("pill"), transform: Some((scale: (1.0, 3.0, 1.0))),
     collider: Some((shape: Capsule(half_height: 1.5, radius: 0.6)))),
    (name: Some("plain"), transform: Some(()), collider: Some((shape: Box(half_extents: (0.3, 0.3, 0.3))))),
])"#;

#[test]
fn an_old_scenes_colliders_on_scaled_entities_are_divided_by_the_world_scale() {
    let scene = parse(OLD);
    assert_eq!(scene.version, SCENE_FORMAT_VERSION);
    assert_eq!(
        shape(&scene, "slab"),
        (
            ColliderShapeFile::Box {
                half_extents: [0.5, 0.5, 0.5]
            },
            [0.0, 1.0, 0.0]
        ),
        "per axis, the offset too"
    );
    // Under a parent scaled 2: world scale 3, so a 1.5 m ball is 0.5 in the entity's units.
    assert_eq!(
        shape(&scene, "ball").0,
        ColliderShapeFile::Sphere { radius: 0.5 }
    );
    // Round shapes take the largest component, as the physics does.
    assert_eq!(
        shape(&scene, "pill").0,
        ColliderShapeFile::Capsule {
            half_height: 0.5,
            radius: 0.2
        }
    );
    assert_eq!(
        shape(&scene, "plain").0,
        ColliderShapeFile::Box {
            half_extents: [0.3, 0.3, 0.3]
        },
        "an unscaled entity's collider is left alone"
    );
}

#[test]
fn a_current_scene_is_read_as_written() {
    let scene = parse(&OLD.replacen("version: 2", "version: 3", 1));
    assert_eq!(
        shape(&scene, "slab").0,
        ColliderShapeFile::Box {
            half_extents: [2.0, 0.25, 1.0]
        }
    );
}

/// The physical check: a box from a version-2 file, 2 m wide in the file and drawn by a
/// scale of 2, rests on the ground with its centre 1 m up — the size it always had — and
/// the same box in a version-3 file (a unit collider scaled by 2) rests there too.
#[test]
fn an_old_scaled_box_rests_at_the_height_it_always_had() {
    for text in [
        r#"(version: 2, entities: [
            (name: Some("ground"), transform: Some(()), collider: Some((shape: Plane))),
            (name: Some("box"), transform: Some((translation: (0.0, 1.5, 0.0), scale: (2.0, 2.0, 2.0))),
             rigid_body: Some((kind: Dynamic)), collider: Some((shape: Box(half_extents: (1.0, 1.0, 1.0))))),
        ])"#,
        r#"(version: 3, entities: [
            (name: Some("ground"), transform: Some(()), collider: Some((shape: Plane))),
            (name: Some("box"), transform: Some((translation: (0.0, 1.5, 0.0), scale: (2.0, 2.0, 2.0))),
             rigid_body: Some((kind: Dynamic)), collider: Some((shape: Box(half_extents: (0.5, 0.5, 0.5))))),
        ])"#,
    ] {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let path = dir.path().join("scene.ron");
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{e}"));
        let mut host = HeadlessHost::new();
        host.load_scene(&path).unwrap_or_else(|e| panic!("{e}"));
        host.step(120);
        let (_, body) = host.find::<RigidBody>("box").expect("the box");
        let (_, pose) = host.find::<Transform>("box").expect("the box");
        assert!(body.grounded, "it landed: {body:?}");
        assert!(
            (pose.translation.y - 1.0).abs() < 0.02,
            "a 2 m box rests with its centre 1 m up, got {}",
            pose.translation.y
        );
    }
}
