//! One mesh of a glTF file named as `file.glb#mesh/N` ([`SubAsset`]), as a scene imported
//! from glTF draws it: each mesh alone, in its own space. Uses the Khronos samples in
//! `../shared/fixtures/gltf/`; skips, saying so, when absent.

mod common;

use std::path::Path;

use glam::Mat4;
use onyx_render::mesh::load_model_geometry;
use onyx_render::{ImportSettings, ModelLoadError, ModelSource, SubAsset};

fn mesh(file: &Path, index: usize) -> Result<ModelSource, ModelLoadError> {
    ModelSource::load(
        &SubAsset::Mesh(index).path_in(file),
        &ImportSettings::default(),
        4096,
    )
}

#[test]
fn a_mesh_reference_reads_that_mesh_alone_without_its_node_transform() {
    let Some(dir) = common::fixture("gltf") else {
        return;
    };
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
    let Some(dir) = common::fixture("gltf") else {
        return;
    };
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
    let Some(dir) = common::fixture("gltf") else {
        return;
    };
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
    let Some(dir) = common::fixture("gltf") else {
        return;
    };
    let model = mesh(&dir.join("BoxTextured/glTF-Binary/BoxTextured.glb"), 0)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(model.problems.is_empty(), "{:?}", model.problems);
    assert_eq!(model.images.len(), 1);
    assert!(model.images.values().all(Option::is_some));
}

#[test]
fn the_meshes_of_one_file_share_one_read_and_one_decode_of_each_image() {
    use std::collections::HashMap;
    use std::sync::Arc;

    use onyx_render::model_material::ImageSource;
    use onyx_render::texture::TextureSource;
    use onyx_render::GltfFiles;

    let Some(dir) = common::fixture("gltf") else {
        return;
    };
    let file = dir.join("TextureCoordinateTest/glTF/TextureCoordinateTest.gltf");
    let settings = ImportSettings::default();
    let files = GltfFiles::default();
    // As a scene asks for its meshes: every load holds the file before the first reads it.
    let leases: Vec<_> = (0..5).map(|_| files.lease(&file)).collect();
    assert_eq!(files.held(), 1, "one file, held once");
    let mut seen: HashMap<ImageSource, Arc<TextureSource>> = HashMap::new();
    let mut shared = 0;
    for (index, lease) in leases.iter().enumerate() {
        let path = SubAsset::Mesh(index).path_in(&file);
        let model = ModelSource::load_leased(&path, &settings, 4096, Some(lease))
            .unwrap_or_else(|e| panic!("mesh {index}: {e}"));
        for (source, image) in model.images {
            let image = image.unwrap_or_else(|| panic!("mesh {index}: {source} failed"));
            if let Some(first) = seen.get(&source) {
                assert!(Arc::ptr_eq(first, &image), "{source} decoded twice");
                shared += 1;
            } else {
                seen.insert(source, image);
            }
        }
    }
    assert!(
        shared > 0,
        "the file's meshes share no image: the test proves nothing"
    );
    drop(leases);
    assert_eq!(files.held(), 0, "the file is let go with its last load");
    // Without a lease each load reads (and decodes) for itself.
    let (source, first) = seen.into_iter().next().unwrap_or_else(|| unreachable!());
    let alone = mesh(&file, 0).unwrap_or_else(|e| panic!("{e}"));
    if let Some(Some(again)) = alone.images.get(&source) {
        assert!(!Arc::ptr_eq(&first, again));
    }
}
