//! glTF files opened as scenes: the Khronos samples in `../shared/fixtures/gltf/` imported
//! as entities (hierarchy, names, transforms, cameras, lights) and spawned into a headless
//! host. Skips, saying so, when the samples are absent.

mod common;

use std::path::Path;

use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::{Camera, Light, MeshRenderer, Name, Parent, Projection, Transform};
use onyx_render::ImportSettings;
use onyx_runtime::scene::{import_gltf_scene, GltfImportError, SceneEntity};
use onyx_runtime::HeadlessHost;

fn import(path: &Path) -> (Vec<SceneEntity>, Vec<String>) {
    match import_gltf_scene(path, false, &ImportSettings::default()) {
        Ok(scene) => (scene.scene.entities, scene.warnings),
        Err(error) => panic!("{}: {error}", path.display()),
    }
}

fn named<'a>(entities: &'a [SceneEntity], name: &str) -> &'a SceneEntity {
    entities
        .iter()
        .find(|e| e.name.as_deref() == Some(name))
        .unwrap_or_else(|| panic!("no entity named {name:?} in {entities:#?}"))
}

fn id_of(entities: &[SceneEntity], name: &str) -> Option<u64> {
    named(entities, name).id
}

#[test]
fn box_is_a_root_a_turned_node_and_its_mesh() {
    let Some(dir) = common::gltf_samples() else {
        return;
    };
    for file in ["Box/glTF/Box.gltf", "Box/glTF-Binary/Box.glb"] {
        let (entities, warnings) = import(&dir.join(file));
        assert!(warnings.is_empty(), "{file}: {warnings:?}");
        // The root named after the file, node 0 (a matrix) under it, node 1 (the mesh) under
        // node 0.
        assert_eq!(entities.len(), 3, "{file}: {entities:#?}");
        let root = named(&entities, "Box");
        assert_eq!(root.parent, None);
        let turned = named(&entities, "node 0");
        assert_eq!(turned.parent, root.id);
        // Its matrix turns +Y to -Z: -90° about X.
        let rotation = turned.transform.map_or(Quat::NAN, |t| t.rotation);
        let expected = Quat::from_rotation_x(-std::f32::consts::FRAC_PI_2);
        assert!(
            rotation.abs_diff_eq(expected, 1e-6) || rotation.abs_diff_eq(-expected, 1e-6),
            "{file}: rotation {rotation}, expected {expected}"
        );
        let mesh = named(&entities, "node 1");
        assert_eq!(mesh.parent, turned.id);
        let renderer = mesh.mesh_renderer.as_ref().map(|r| r.mesh.as_str());
        let name = Path::new(file).file_name().map(|n| n.to_string_lossy());
        assert_eq!(
            renderer,
            Some(format!("{}#mesh/0", name.unwrap_or_default())).as_deref()
        );
    }
}

#[test]
fn box_animated_keeps_both_root_nodes_and_the_chain_under_the_first() {
    let Some(dir) = common::gltf_samples() else {
        return;
    };
    let (entities, _) = import(&dir.join("BoxAnimated/glTF-Binary/BoxAnimated.glb"));
    assert_eq!(entities.len(), 5, "{entities:#?}");
    let root = id_of(&entities, "BoxAnimated");
    // Scene roots: node 3 (a mesh) and node 0 → 1 → 2 (a mesh).
    assert_eq!(named(&entities, "node 3").parent, root);
    assert_eq!(named(&entities, "node 0").parent, root);
    assert_eq!(
        named(&entities, "node 1").parent,
        id_of(&entities, "node 0")
    );
    assert_eq!(
        named(&entities, "node 2").parent,
        id_of(&entities, "node 1")
    );
    let meshes: Vec<&str> = entities
        .iter()
        .filter_map(|e| e.mesh_renderer.as_ref().map(|r| r.mesh.as_str()))
        .collect();
    assert_eq!(meshes, ["BoxAnimated.glb#mesh/1", "BoxAnimated.glb#mesh/0"]);
}

#[test]
fn cameras_become_a_perspective_and_an_orthographic_camera_the_first_active() {
    let Some(dir) = common::gltf_samples() else {
        return;
    };
    for file in [
        "Cameras/glTF/Cameras.gltf",
        "Cameras/glTF-Embedded/Cameras.gltf",
    ] {
        let (entities, _) = import(&dir.join(file));
        let cameras: Vec<(Camera, Transform)> = entities
            .iter()
            .filter_map(|e| Some((e.camera?, e.transform?)))
            .collect();
        assert_eq!(cameras.len(), 2, "{file}");
        let (perspective, at) = cameras[0];
        assert_eq!(
            perspective.projection,
            Projection::Perspective { fov_y: 0.7 }
        );
        assert_eq!((perspective.near, perspective.far), (0.01, 100.0));
        assert!(perspective.active);
        assert_eq!(at.translation, Vec3::new(0.5, 0.5, 3.0));
        let (orthographic, _) = cameras[1];
        // ymag is half the visible height.
        assert_eq!(
            orthographic.projection,
            Projection::Orthographic { height: 2.0 }
        );
        assert!(
            !orthographic.active,
            "{file}: only the first camera is active"
        );
    }
}

#[test]
fn lamp_lights_are_point_lights_at_their_nodes_and_the_unknown_extension_warned_once() {
    let Some(dir) = common::gltf_samples() else {
        return;
    };
    let (entities, warnings) = import(&dir.join("LightsPunctualLamp/glTF/LightsPunctualLamp.gltf"));
    let lights: Vec<(&str, Light, Transform)> = entities
        .iter()
        .filter_map(|e| Some((e.name.as_deref()?, e.light?, e.transform?)))
        .collect();
    assert_eq!(lights.len(), 5);
    let (name, light, at) = lights[0];
    assert_eq!(name, "Point_Orientation");
    let Light::Point {
        color,
        intensity,
        range,
        ..
    } = light
    else {
        panic!("{light:?}")
    };
    assert_eq!(color, [1.0, 0.631_875, 0.239_099_76]);
    assert_eq!(
        intensity,
        15.0 * onyx_runtime::scene::gltf_import::ONYX_PER_CANDELA
    );
    // No range in the file: where 15 cd falls to 0.01 lux.
    assert!((range - (15.0f32 / 0.01).sqrt()).abs() < 1e-3, "{range}");
    assert!(at
        .translation
        .abs_diff_eq(Vec3::new(0.046_223_555, 0.907_797_3, 0.006_696_63), 1e-6));
    // The file uses KHR_materials_transmission: one warning naming it.
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(warnings[0].contains("KHR_materials_transmission"));
}

#[test]
fn orientation_test_nodes_keep_their_rotations() {
    let Some(dir) = common::gltf_samples() else {
        return;
    };
    let path = dir.join("OrientationTest/glTF/OrientationTest.gltf");
    let json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&path).unwrap_or_else(|e| panic!("{e}")))
            .unwrap_or_else(|e| panic!("{e}"));
    let (entities, _) = import(&path);
    let nodes = json["nodes"].as_array().map_or(0, Vec::len);
    assert_eq!(entities.len(), 1 + nodes);
    for node in json["nodes"].as_array().into_iter().flatten() {
        let (Some(name), Some(r)) = (node["name"].as_str(), node["rotation"].as_array()) else {
            continue;
        };
        let r: Vec<f32> = r
            .iter()
            .filter_map(|v| v.as_f64())
            .map(|v| v as f32)
            .collect();
        let expected = Quat::from_slice(&r).normalize();
        let got = named(&entities, name)
            .transform
            .map_or(Quat::NAN, |t| t.rotation);
        assert!(
            got.abs_diff_eq(expected, 1e-6),
            "{name}: {got} != {expected}"
        );
    }
}

#[test]
fn a_skinned_file_loads_in_bind_pose_with_one_warning_naming_skins() {
    let Some(dir) = common::gltf_samples() else {
        return;
    };
    for file in [
        "CesiumMan/glTF/CesiumMan.gltf",
        "CesiumMan/glTF-Binary/CesiumMan.glb",
    ] {
        let (entities, warnings) = import(&dir.join(file));
        assert!(entities.iter().any(|e| e.mesh_renderer.is_some()), "{file}");
        let skins: Vec<&String> = warnings.iter().filter(|w| w.contains("skins")).collect();
        assert_eq!(skins.len(), 1, "{file}: {warnings:?}");
    }
    let (_, warnings) = import(&dir.join("AnimatedMorphCube/glTF-Binary/AnimatedMorphCube.glb"));
    assert_eq!(
        warnings
            .iter()
            .filter(|w| w.contains("morph targets"))
            .count(),
        1,
        "{warnings:?}"
    );
}

#[test]
fn a_required_unknown_extension_is_a_clear_error() {
    let dir = std::env::temp_dir().join(format!("onyx-gltf-required-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let path = dir.join("needs.gltf");
    std::fs::write(
        &path,
        r#"{"asset":{"version":"2.0"},"extensionsUsed":["EXT_future"],"extensionsRequired":["EXT_future"]}"#,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    match import_gltf_scene(&path, true, &ImportSettings::default()) {
        Err(error @ GltfImportError::RequiredExtension { .. }) => {
            assert!(error.to_string().contains("EXT_future"), "{error}");
        }
        other => panic!("expected a required-extension error, got {other:?}"),
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_gltf_scene_spawns_with_parents_world_poses_and_a_default_view() {
    let Some(dir) = common::gltf_samples() else {
        return;
    };
    let path = dir.join("BoxAnimated/glTF/BoxAnimated.gltf");
    let mut host = HeadlessHost::new();
    // Root + 4 nodes + the default camera, sun and ambient light (the file has none).
    assert_eq!(host.load_scene(&path).map_err(|e| e.to_string()), Ok(8));
    host.step(1);
    let (node0, _) = host
        .find::<Transform>("node 0")
        .unwrap_or_else(|| panic!("node 0 not spawned"));
    let (node1, parent) = host
        .find::<Parent>("node 1")
        .unwrap_or_else(|| panic!("node 1 has no parent"));
    assert_eq!(parent.0, node0);
    assert!(host.get::<MeshRenderer>(node1).is_none());
    let (_, camera) = host
        .find::<Camera>("camera")
        .unwrap_or_else(|| panic!("no default camera"));
    assert!(camera.active);
    assert!(host.find::<Light>("sun").is_some());
    // Opening a model is not choosing where the scene is saved.
    assert_eq!(host.host().scene_path(), None);
    let names: Vec<String> = host
        .world()
        .query::<&Name>()
        .iter()
        .map(|n| n.0.clone())
        .collect();
    assert!(names.contains(&"BoxAnimated".to_owned()), "{names:?}");
}

#[test]
fn a_file_the_gltf_crate_panics_on_is_an_error_naming_it() {
    //! The gltf crate's validation indexes `accessors` with a primitive's POSITION before
    //! checking it: such a file panicked inside the import.
    let dir = std::env::temp_dir().join(format!("onyx-gltf-panic-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let path = dir.join("bad-position.gltf");
    std::fs::write(
        &path,
        r#"{"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{"POSITION":99}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]}"#,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    match import_gltf_scene(&path, true, &ImportSettings::default()) {
        Err(error @ GltfImportError::Invalid { .. }) => {
            assert!(error.to_string().contains("bad-position.gltf"), "{error}");
        }
        other => panic!("expected an invalid-file error, got {other:?}"),
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Spot lights shone as point lights (Onyx had none); now they keep their cones, clamped
/// to what `Light::Spot` accepts (outer below 90°, inner below outer).
#[test]
fn spot_lights_keep_their_cones_and_suns_cast_shadows() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("spots.gltf");
    let text = r#"{
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "spot", "intensity": 100, "range": 8,
             "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}},
            {"type": "spot", "intensity": 100,
             "spot": {"innerConeAngle": 1.5, "outerConeAngle": 1.5707964}},
            {"type": "directional", "intensity": 3}
        ]}},
        "nodes": [
            {"name": "a", "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"name": "b", "extensions": {"KHR_lights_punctual": {"light": 1}}},
            {"name": "sun", "extensions": {"KHR_lights_punctual": {"light": 2}}}
        ],
        "scenes": [{"nodes": [0, 1, 2]}],
        "scene": 0
    }"#;
    std::fs::write(&path, text).unwrap_or_else(|e| panic!("{e}"));
    let (entities, warnings) = import(&path);
    assert!(warnings.iter().all(|w| !w.contains("spot")), "{warnings:?}");
    let Some(Light::Spot {
        range,
        inner_angle,
        outer_angle,
        shadows,
        ..
    }) = named(&entities, "a").light
    else {
        panic!("{:?}", named(&entities, "a").light)
    };
    assert_eq!(
        (range, inner_angle, outer_angle, shadows),
        (8.0, 0.2, 0.5, false)
    );
    let Some(Light::Spot {
        inner_angle,
        outer_angle,
        ..
    }) = named(&entities, "b").light
    else {
        panic!("{:?}", named(&entities, "b").light)
    };
    assert!(outer_angle < std::f32::consts::FRAC_PI_2, "{outer_angle}");
    assert!(inner_angle < outer_angle, "{inner_angle} {outer_angle}");
    assert!(matches!(
        named(&entities, "sun").light,
        Some(Light::Directional { shadows: true, .. })
    ));
}
