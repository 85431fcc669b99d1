//! Import settings a scene gives per model (`imports: { "model.obj": (scale, up_axis,
//! normals) }`): applied where the model's geometry is read (tools' bounds, colliders, the
//! renderer), checked on load, and saved back.

use std::path::{Path, PathBuf};

use onyx_plugin_api::__ffi::with_ctx;
use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::Transform;
use onyx_runtime::scene::{read_scene, SceneError};
use onyx_runtime::HeadlessHost;

fn model() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../assets/models/no_normals.obj")
}

fn scene(dir: &Path, imports: &str) -> PathBuf {
    let path = dir.join("scene.ron");
    let text = format!(
        r#"(
    version: 2,
    imports: {{ "{model}": {imports} }},
    entities: [
        (name: Some("tetra"), transform: Some(()), mesh_renderer: Some((mesh: "{model}"))),
    ],
)"#,
        model = model().display()
    );
    std::fs::write(&path, text).unwrap_or_else(|e| panic!("{e}"));
    path
}

#[test]
fn a_scaled_z_up_model_is_turned_to_y_up_and_scaled() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = scene(dir.path(), "(scale: Some(2.0), up_axis: Z, normals: Flat)");
    let mut host = HeadlessHost::new();
    host.load_scene(&path).unwrap_or_else(|e| panic!("{e}"));
    let (tetra, _) = host
        .find::<Transform>("tetra")
        .unwrap_or_else(|| panic!("no tetra"));
    let bounds = host
        .host_mut()
        .with_services("test", |s| with_ctx(s, |ctx| ctx.local_bounds(tetra)))
        .unwrap_or_else(|| panic!("no bounds"));
    // The file: x -1..1, y -0.5..1, z -1..0.8. Z up to Y up: (x, y, z) → (x, z, -y); ×2.
    let expected_min = Vec3::new(-1.0, -1.0, -1.0) * 2.0;
    let expected_max = Vec3::new(1.0, 0.8, 0.5) * 2.0;
    assert!(
        bounds.min.abs_diff_eq(expected_min, 1e-5) && bounds.max.abs_diff_eq(expected_max, 1e-5),
        "bounds {:?}..{:?}, expected {expected_min}..{expected_max}",
        bounds.min,
        bounds.max
    );
    // Saved back under the model's path.
    let saved = dir.path().join("saved.ron");
    host.host()
        .save_scene(&saved)
        .unwrap_or_else(|e| panic!("{e}"));
    let file = read_scene(&saved).unwrap_or_else(|e| panic!("{e}"));
    let settings = file
        .imports
        .values()
        .next()
        .map(|s| s.settings())
        .unwrap_or_else(|| panic!("no imports saved: {file:?}"));
    assert_eq!(settings.map(|s| s.scale), Ok(2.0));
}

#[test]
fn a_scale_out_of_range_is_refused_naming_the_model() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = scene(dir.path(), "(scale: Some(0.0))");
    match read_scene(&path) {
        Err(error @ SceneError::InvalidImport { .. }) => {
            let text = error.to_string();
            assert!(
                text.contains("no_normals.obj") && text.contains("scale"),
                "{text}"
            );
        }
        other => panic!("expected an import-settings error, got {other:?}"),
    }
}
