//! The Khronos glTF 2.0 sample models in `../shared/fixtures/gltf/` (every variant there:
//! glTF, glTF-Binary, glTF-Embedded), read on the CPU: structure checked against the files'
//! own numbers, each unsupported feature named once. Skips, saying so, when absent.

mod common;

use std::path::{Path, PathBuf};

use glam::{Mat4, Vec3};
use onyx_render::model_material::{AlphaMode, ImageSource};
use onyx_render::{ImportSettings, ModelLoadError, ModelSource};

/// Every `.gltf` / `.glb` file under the samples folder.
fn every_file(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for entry in entries.flatten() {
            let p = entry.path();
            if p.is_dir() {
                stack.push(p);
            } else if onyx_render::mesh::is_gltf(&p) {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

fn load(path: &Path) -> ModelSource {
    match ModelSource::load(path, &ImportSettings::default(), 8192) {
        Ok(model) => model,
        Err(error) => panic!("{}: {error}", path.display()),
    }
}

#[test]
fn every_sample_in_every_variant_loads_and_names_each_unsupported_feature_once() {
    let Some(dir) = common::fixture("gltf") else {
        return;
    };
    let files = every_file(&dir);
    assert!(files.len() >= 28, "found only {} glTF files", files.len());
    for path in &files {
        let model = load(path);
        assert!(
            model.triangle_count() > 0,
            "{}: no triangles",
            path.display()
        );
        let mut messages: Vec<&str> = model.warnings.iter().map(|w| w.message.as_str()).collect();
        let before = messages.len();
        messages.sort_unstable();
        messages.dedup();
        assert_eq!(
            messages.len(),
            before,
            "{}: a warning repeats: {:?}",
            path.display(),
            model.warnings
        );
        assert!(
            model.problems.is_empty(),
            "{}: {:?}",
            path.display(),
            model.problems
        );
    }
}

#[test]
fn box_variants_give_twelve_triangles_turned_by_the_root_matrix() {
    let Some(dir) = common::fixture("gltf") else {
        return;
    };
    // The root node's matrix (column-major in the file): +Y becomes -Z, +Z becomes +Y.
    let expected = Mat4::from_cols_array(&[
        1., 0., 0., 0., 0., 0., -1., 0., 0., 1., 0., 0., 0., 0., 0., 1.,
    ]);
    for file in [
        "Box/glTF/Box.gltf",
        "Box/glTF-Binary/Box.glb",
        "Box-embedded-from-index.gltf",
    ] {
        let model = load(&dir.join(file));
        assert_eq!(model.triangle_count(), 12, "{file}");
        assert_eq!(model.parts.len(), 1, "{file}");
        assert!(
            model.parts[0].transform.abs_diff_eq(expected, 1e-6),
            "{file}: {}",
            model.parts[0].transform
        );
        for v in &model.parts[0].mesh.vertices {
            let n = Vec3::from(v.normal);
            assert!(
                (n.length() - 1.0).abs() < 1e-4 && n.abs().max_element() > 0.999,
                "{file}: normal {n}"
            );
        }
    }
}

#[test]
fn sparse_accessor_values_replace_the_base_positions() {
    let Some(dir) = common::fixture("gltf") else {
        return;
    };
    let gltf_path = dir.join("SimpleSparseAccessor/glTF/SimpleSparseAccessor.gltf");
    let json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&gltf_path).unwrap_or_default())
            .unwrap_or_else(|e| panic!("{e}"));
    let bin = std::fs::read(dir.join("SimpleSparseAccessor/glTF/SimpleSparseAccessor.bin"))
        .unwrap_or_default();
    // Expected: the base vec3 floats, with the sparse indices' values written over them,
    // read straight from the bytes.
    let view = |i: u64| {
        let v = &json["bufferViews"][i as usize];
        v["byteOffset"].as_u64().unwrap_or(0) as usize
    };
    let accessor = &json["accessors"][1];
    let count = accessor["count"].as_u64().unwrap_or(0) as usize;
    let base = view(accessor["bufferView"].as_u64().unwrap_or(0));
    let f = |at: usize| f32::from_le_bytes([bin[at], bin[at + 1], bin[at + 2], bin[at + 3]]);
    let mut expected: Vec<[f32; 3]> = (0..count)
        .map(|i| [f(base + 12 * i), f(base + 12 * i + 4), f(base + 12 * i + 8)])
        .collect();
    let sparse = &accessor["sparse"];
    let indices = view(sparse["indices"]["bufferView"].as_u64().unwrap_or(0));
    let values = view(sparse["values"]["bufferView"].as_u64().unwrap_or(0));
    for k in 0..sparse["count"].as_u64().unwrap_or(0) as usize {
        let i = u16::from_le_bytes([bin[indices + 2 * k], bin[indices + 2 * k + 1]]) as usize;
        expected[i] = [
            f(values + 12 * k),
            f(values + 12 * k + 4),
            f(values + 12 * k + 8),
        ];
    }
    assert!(
        expected.iter().any(|p| p[1] > 2.0),
        "the sample raises some vertices"
    );
    for variant in [
        "glTF/SimpleSparseAccessor.gltf",
        "glTF-Embedded/SimpleSparseAccessor.gltf",
    ] {
        let model = load(&dir.join("SimpleSparseAccessor").join(variant));
        let mut got: Vec<[f32; 3]> = model.parts[0]
            .mesh
            .vertices
            .iter()
            .map(|v| v.position)
            .collect();
        let mut want = expected.clone();
        let key = |p: &[f32; 3]| p.map(f32::to_bits);
        got.sort_by_key(key);
        got.dedup();
        want.sort_by_key(key);
        want.dedup();
        assert_eq!(got, want, "{variant}");
    }
}

#[test]
fn damaged_helmet_carries_every_metallic_roughness_slot() {
    let Some(dir) = common::fixture("gltf") else {
        return;
    };
    for file in [
        "DamagedHelmet/glTF/DamagedHelmet.gltf",
        "DamagedHelmet/glTF-Binary/DamagedHelmet.glb",
    ] {
        let model = load(&dir.join(file));
        let m = &model.parts[0].material;
        assert!(
            m.base_color_texture.is_some() && m.metallic_roughness_texture.is_some(),
            "{file}"
        );
        assert!(
            m.normal_texture.is_some()
                && m.occlusion_texture.is_some()
                && m.emissive_texture.is_some(),
            "{file}"
        );
        assert_eq!(m.emissive, [1.0, 1.0, 1.0], "{file}");
        let Some(slot) = &m.base_color_texture else {
            continue;
        };
        let decoded = model.images.get(&slot.image).and_then(Option::as_ref);
        assert_eq!(
            decoded.map(|t| t.original_size),
            Some((2048, 2048)),
            "{file}"
        );
        if file.ends_with(".glb") {
            assert!(matches!(slot.image, ImageSource::Embedded { .. }), "{file}");
        }
    }
}

#[test]
fn alpha_modes_and_texture_transforms_are_read() {
    let Some(dir) = common::fixture("gltf") else {
        return;
    };
    let alpha = load(&dir.join("AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf"));
    let modes: Vec<AlphaMode> = alpha.parts.iter().map(|p| p.material.alpha_mode).collect();
    assert!(
        modes.contains(&AlphaMode::Blend)
            && modes.iter().any(|m| matches!(m, AlphaMode::Mask { .. })),
        "{modes:?}"
    );
    let transform = load(&dir.join("TextureTransformTest/glTF/TextureTransformTest.gltf"));
    assert!(
        transform.parts.iter().any(|p| p
            .material
            .base_color_texture
            .as_ref()
            .is_some_and(|t| !t.transform.is_identity())),
        "no KHR_texture_transform read"
    );
}

#[test]
fn skins_and_morph_targets_load_in_bind_pose_with_one_warning() {
    let Some(dir) = common::fixture("gltf") else {
        return;
    };
    let skinned = load(&dir.join("CesiumMan/glTF/CesiumMan.gltf"));
    assert_eq!(
        skinned
            .warnings
            .iter()
            .filter(|w| w.message.contains("skins"))
            .count(),
        1,
        "{:?}",
        skinned.warnings
    );
    let morph = load(&dir.join("AnimatedMorphCube/glTF-Binary/AnimatedMorphCube.glb"));
    assert_eq!(
        morph
            .warnings
            .iter()
            .filter(|w| w.message.contains("morph targets"))
            .count(),
        1,
        "{:?}",
        morph.warnings
    );
}

#[test]
fn a_required_unknown_extension_is_a_clear_error_and_a_used_one_a_warning() {
    let dir = std::env::temp_dir().join(format!("onyx-gltf-ext-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let doc = |required: &str| {
        format!(
            r#"{{"asset":{{"version":"2.0"}},"extensionsUsed":["EXT_made_up"],"extensionsRequired":[{required}],
            "buffers":[{{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}}],
            "bufferViews":[{{"buffer":0,"byteLength":36}}],
            "accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}}],
            "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
            "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}],"scene":0}}"#
        )
    };
    std::fs::write(dir.join("req.gltf"), doc(r#""EXT_made_up""#)).unwrap_or_else(|e| panic!("{e}"));
    match ModelSource::load(&dir.join("req.gltf"), &ImportSettings::default(), 8192) {
        Err(error @ ModelLoadError::RequiredExtension { .. }) => {
            assert!(
                error.to_string().contains("EXT_made_up") && error.to_string().contains("req.gltf"),
                "{error}"
            );
        }
        other => panic!("expected RequiredExtension, got {other:?}"),
    }
    std::fs::write(dir.join("used.gltf"), doc("")).unwrap_or_else(|e| panic!("{e}"));
    let model = load(&dir.join("used.gltf"));
    assert_eq!(model.triangle_count(), 1);
    assert_eq!(
        model
            .warnings
            .iter()
            .filter(|w| w.message.contains("EXT_made_up"))
            .count(),
        1
    );
    let _ = std::fs::remove_dir_all(&dir);
}
