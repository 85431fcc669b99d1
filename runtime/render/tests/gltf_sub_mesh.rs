//! One mesh of a glTF file named as `file.glb#mesh/N` ([`SubAsset`]), as a scene imported
//! from glTF draws it: each mesh alone, in its own space. Uses the Khronos samples in
//! `../shared/fixtures/gltf/`; skips, saying so, when absent.

mod common;

use std::path::{Path, PathBuf};

use glam::Mat4;
use onyx_render::mesh::load_model_geometry;
use onyx_render::{ImportSettings, ModelLoadError, ModelSource, SubAsset};

fn samples() -> Option<PathBuf> {
    let dir = common::fixtures().join("gltf");
    if dir.is_dir() {
        Some(dir)
    } else {
        eprintln!(
            "skipped: {} is absent (../shared/fixtures not beside the checkout)",
            dir.display()
        );
        None
    }
}

fn mesh(file: &Path, index: usize) -> Result<ModelSource, ModelLoadError> {
    ModelSource::load(
        &SubAsset::Mesh(index).path_in(file),
        &ImportSettings::default(),
        4096,
    )
}

#[test]
fn a_mesh_reference_reads_that_mesh_alone_without_its_node_transform() {
    let Some(dir) = samples() else { return };
    for file in ["Box/glTF-Binary/Box.glb", "Box/glTF/Box.gltf"] {
        let model = mesh(&dir.join(file), 0).unwrap_or_else(|e| panic!("{file}: {e}"));
        assert_eq!(model.triangle_count(), 12, "{file}");
        // The whole-file reader applies the root node's matrix; one mesh is in its own space.
        assert_eq!(model.parts[0].transform, Mat4::IDENTITY, "{file}");
        assert!(model.warnings.is_empty(), "{file}: {:?}", model.warnings);
    }
}

#[test]
fn each_mesh_of_a_many_mesh_file_is_its_own_triangles() {
    let Some(dir) = samples() else { return };
    // SimpleMeshes: two nodes share mesh 0 (one triangle): the whole file draws it twice.
    let file = dir.join("SimpleMeshes/glTF/SimpleMeshes.gltf");
    let whole = ModelSource::load(&file, &ImportSettings::default(), 4096)
        .unwrap_or_else(|e| panic!("{e}"));
    let one = mesh(&file, 0).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(one.triangle_count(), 1);
    assert_eq!(whole.triangle_count(), 2 * one.triangle_count());
    // Geometry for colliders goes through the same reference.
    let geometry = load_model_geometry(
        &SubAsset::Mesh(0).path_in(&file),
        &ImportSettings::default(),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(geometry.triangle_count(), 1);
}

#[test]
fn a_mesh_the_file_lacks_is_an_error_saying_how_many_it_has() {
    let Some(dir) = samples() else { return };
    let file = dir.join("Box/glTF-Binary/Box.glb");
    match mesh(&file, 7) {
        Err(error @ ModelLoadError::Gltf { .. }) => {
            let text = error.to_string();
            assert!(
                text.contains("1 mesh") && text.contains("#mesh/7"),
                "{text}"
            );
        }
        other => panic!("expected an error naming the mesh count, got {other:?}"),
    }
}

#[test]
fn an_embedded_texture_of_one_mesh_is_decoded_with_it() {
    let Some(dir) = samples() else { return };
    let model = mesh(&dir.join("BoxTextured/glTF-Binary/BoxTextured.glb"), 0)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(model.problems.is_empty(), "{:?}", model.problems);
    assert_eq!(model.images.len(), 1);
    assert!(model.images.values().all(Option::is_some));
}
