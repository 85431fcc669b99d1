//! Asset loading: OBJ/MTL/texture happy paths, the cache, and every bad-asset case giving a
//! typed error that names the file plus a fallback that still draws.

mod common;

use std::path::Path;

use glam::{Mat4, Vec3};
use onyx_render::{
    Camera, DrawObject, Lights, MeshData, ModelLoadError, RenderScene, ShadingMode,
    TextureLoadError, Vertex,
};

fn ends_with(path: &Path, name: &str) -> bool {
    path.file_name().is_some_and(|f| f == name)
}

/// Renders a model at the origin and returns the share of magenta-ish pixels (red and blue
/// strong, green under half of them: magenta after tone mapping).
fn magenta_share(renderer: &mut onyx_render::Renderer, model: &onyx_render::Model) -> f64 {
    let objects: Vec<DrawObject> = model.draw_objects(Mat4::IDENTITY).collect();
    let lights = Lights {
        ambient: Vec3::ONE,
        sun: None,
        points: Vec::new(),
        spots: Vec::new(),
    };
    let camera = Camera::perspective_look_at(
        Vec3::new(0.3, 0.4, 2.0),
        Vec3::new(0.3, 0.3, 0.0),
        1.0,
        0.1,
        10.0,
    );
    let scene = RenderScene::new(camera, &lights).with_objects(&objects);
    let image = common::render_image(renderer, 64, 64, &scene);
    let magenta = image
        .pixels()
        .filter(|p| {
            p.0[0] > 150 && p.0[2] > 150 && u16::from(p.0[1]) * 2 < u16::from(p.0[0].min(p.0[2]))
        })
        .count();
    magenta as f64 / f64::from(64 * 64)
}

#[test]
fn missing_obj_is_a_typed_error_and_the_fallback_cube_draws() {
    let mut renderer = common::renderer();
    let path = common::assets().join("models/no_such_model.obj");
    match renderer.load_model(&path) {
        Err(ModelLoadError::Read { path: p, .. }) => assert_eq!(p, path),
        other => panic!("expected Read, got {other:?}"),
    }
    let (model, problems) = renderer.load_model_or_fallback(&path);
    assert_eq!(problems.len(), 1);
    assert!(
        problems[0].to_string().contains("no_such_model.obj"),
        "message must name the file: {}",
        problems[0]
    );
    assert_eq!(model, renderer.fallback_model());
    assert!(
        magenta_share(&mut renderer, &model) > 0.05,
        "the fallback must be visibly magenta"
    );
}

#[test]
fn malformed_obj_is_a_parse_error_naming_the_file() {
    let mut renderer = common::renderer();
    let path = common::assets().join("broken/malformed.obj");
    let error = match renderer.load_model(&path) {
        Err(error @ ModelLoadError::ObjParse { .. }) => error,
        other => panic!("expected ObjParse, got {other:?}"),
    };
    assert!(error.to_string().contains("malformed.obj"), "{error}");
    let (model, problems) = renderer.load_model_or_fallback(&path);
    assert_eq!((problems.len(), model.parts.len()), (1, 1));
}

#[test]
fn missing_mtl_names_the_mtl_and_parts_get_the_checker() {
    let mut renderer = common::renderer();
    let path = common::assets().join("broken/missing_mtl.obj");
    match renderer.load_model(&path) {
        Err(ModelLoadError::Mtl { obj, mtl, .. }) => {
            assert_eq!(obj, path);
            assert!(ends_with(&mtl, "does_not_exist.mtl"), "{}", mtl.display());
        }
        other => panic!("expected Mtl, got {other:?}"),
    }
    let (model, problems) = renderer.load_model_or_fallback(&path);
    assert_eq!(problems.len(), 1);
    assert!(
        problems[0].to_string().contains("does_not_exist.mtl"),
        "{}",
        problems[0]
    );
    assert_eq!(
        model.parts.len(),
        1,
        "the geometry itself is fine and must be kept"
    );
    assert_eq!(
        model.parts[0].material.texture,
        Some(renderer.fallback_texture())
    );
    assert!(magenta_share(&mut renderer, &model) > 0.01);
}

#[test]
fn missing_texture_names_the_texture_and_uses_the_checker() {
    let mut renderer = common::renderer();
    let path = common::assets().join("broken/missing_texture.obj");
    match renderer.load_model(&path) {
        Err(ModelLoadError::Texture {
            material, source, ..
        }) => {
            assert_eq!(material, "lost");
            let TextureLoadError::Read { path: texture, .. } = *source else {
                panic!("expected Read, got {source:?}")
            };
            assert!(
                ends_with(&texture, "no_such_texture.png"),
                "{}",
                texture.display()
            );
        }
        other => panic!("expected Texture(Read), got {other:?}"),
    }
    let (model, problems) = renderer.load_model_or_fallback(&path);
    assert_eq!(problems.len(), 1);
    assert!(
        problems[0].to_string().contains("no_such_texture.png"),
        "{}",
        problems[0]
    );
    assert_eq!(
        model.parts[0].material.texture,
        Some(renderer.fallback_texture())
    );
    assert!(magenta_share(&mut renderer, &model) > 0.01);
}

#[test]
fn corrupt_png_is_a_decode_error_naming_the_file() {
    let mut renderer = common::renderer();
    let png = common::assets().join("broken/corrupt.png");
    match renderer.load_texture(&png) {
        Err(TextureLoadError::Decode { path, .. }) => assert_eq!(path, png),
        other => panic!("expected Decode, got {other:?}"),
    }
    let (handle, error) = renderer.load_texture_or_fallback(&png);
    assert_eq!(handle, renderer.fallback_texture());
    assert!(error.is_some_and(|e| e.to_string().contains("corrupt.png")));
    // Through a model as well.
    match renderer.load_model(common::assets().join("broken/corrupt_texture.obj")) {
        Err(ModelLoadError::Texture { source, .. }) => {
            let TextureLoadError::Decode { path, .. } = *source else {
                panic!("expected Decode, got {source:?}")
            };
            assert!(ends_with(&path, "corrupt.png"));
        }
        other => panic!("expected Texture(Decode), got {other:?}"),
    }
}

#[test]
fn multi_material_obj_gives_one_part_per_material_and_is_cached() {
    let mut renderer = common::renderer();
    let path = common::assets().join("models/two_materials.obj");
    let model = match renderer.load_model(&path) {
        Ok(model) => model,
        Err(error) => panic!("{error}"),
    };
    assert_eq!(model.parts.len(), 2, "{model:?}");
    let red = &model.parts[0].material;
    assert_eq!(
        (red.color, red.texture, red.shading),
        ([0.9, 0.1, 0.1, 1.0], None, ShadingMode::Lit)
    );
    let textured = model.parts[1].material.texture;
    assert!(textured.is_some());
    let meshes_before = renderer.mesh_count();
    let again = match renderer.load_model(&path) {
        Ok(model) => model,
        Err(error) => panic!("{error}"),
    };
    assert_eq!(again, model, "a second load must return the cached handles");
    assert_eq!(
        renderer.mesh_count(),
        meshes_before,
        "a second load must not upload again"
    );
    let texture = renderer.load_texture(common::assets().join("textures/uv_grid.png"));
    assert_eq!(texture.ok(), textured, "the texture is cached by path");
}

#[test]
fn spot_fixture_loads_with_its_texture() {
    let mut renderer = common::renderer();
    let model = match renderer.load_model(common::fixtures().join("spot/spot_triangulated.obj")) {
        Ok(model) => model,
        Err(error) => panic!("{error}"),
    };
    assert_eq!(model.parts.len(), 1);
    let texture = model.parts[0].material.texture;
    assert_eq!(
        texture.and_then(|t| renderer.texture_size(t)),
        Some((1024, 1024))
    );
}

#[test]
fn normals_are_generated_when_the_obj_has_none() {
    let mut renderer = common::renderer();
    let model = match renderer.load_model(common::assets().join("models/no_normals.obj")) {
        Ok(model) => model,
        Err(error) => panic!("{error}"),
    };
    // Rendered in Normal mode: each face the camera sees shows its own geometric normal
    // (a tetrahedron's 70° edges are sharper than the default crease angle, so it stays
    // faceted), not a flat +Y green.
    let objects: Vec<DrawObject> = model
        .draw_objects(Mat4::IDENTITY)
        .map(|mut o| {
            o.material.shading = ShadingMode::Normal;
            o
        })
        .collect();
    let lights = Lights::default();
    let eye = Vec3::new(-2.2, 1.6, 1.6);
    let camera = Camera::perspective_look_at(eye, Vec3::ZERO, 1.0, 0.1, 10.0);
    let image = common::render_image(
        &mut renderer,
        48,
        48,
        &RenderScene::new(camera, &lights).with_objects(&objects),
    );
    let corners = [
        Vec3::new(0.0, 1.0, 0.0),
        Vec3::new(-1.0, -0.5, 0.8),
        Vec3::new(1.0, -0.5, 0.8),
        Vec3::new(0.0, -0.5, -1.0),
    ];
    let srgb = |c: f32| {
        let c = c.clamp(0.0, 1.0);
        let e = if c <= 0.003_130_8 {
            c * 12.92
        } else {
            1.055 * c.powf(1.0 / 2.4) - 0.055
        };
        (e * 255.0).round() as i32
    };
    let centre = corners.iter().copied().sum::<Vec3>() / 4.0;
    let mut faces_seen = 0;
    for skip in 0..4 {
        let face: Vec<Vec3> = (0..4).filter(|&i| i != skip).map(|i| corners[i]).collect();
        let mut n = (face[1] - face[0]).cross(face[2] - face[0]).normalize();
        let middle = (face[0] + face[1] + face[2]) / 3.0;
        if n.dot(middle - centre) < 0.0 {
            n = -n;
        }
        if n.dot(eye - middle) <= 0.2 {
            continue;
        }
        let want = (n * 0.5 + Vec3::splat(0.5)).to_array().map(srgb);
        let pixels = image
            .pixels()
            .filter(|p| (0..3).all(|c| (i32::from(p.0[c]) - want[c]).abs() <= 3))
            .count();
        assert!(
            pixels > 10,
            "face with normal {n} shows in {pixels} pixels (colour {want:?})"
        );
        faces_seen += 1;
    }
    assert!(faces_seen >= 2, "the camera should see at least two faces");
}

#[test]
fn invalid_mesh_data_is_refused() {
    let mut renderer = common::renderer();
    let bad = MeshData {
        vertices: vec![Vertex::default(); 2],
        indices: vec![0, 1, 2],
    };
    let error = match renderer.add_mesh(&bad, "bad triangle") {
        Err(error) => error,
        Ok(handle) => panic!("accepted an out-of-range index as {handle:?}"),
    };
    assert!(error.to_string().contains("bad triangle"), "{error}");
}

#[test]
fn the_missing_texture_placeholder_shows_on_black_materials_and_meshes_without_uvs() {
    //! The checker was multiplied by the material colour (a black or green wall went dark)
    //! and showed as stripes on meshes without texture coordinates.
    let dir = std::env::temp_dir().join(format!("onyx-placeholder-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let write = |name: &str, text: &str| {
        std::fs::write(dir.join(name), text).unwrap_or_else(|e| panic!("{e}"));
    };
    write("m.mtl", "newmtl black\nKd 0 0 0\nmap_Kd gone.png\n");
    write(
        "quad.obj",
        "mtllib m.mtl\nv -0.5 -0.2 0\nv 1.1 -0.2 0\nv 1.1 0.8 0\nv -0.5 0.8 0\nusemtl black\nf 1 2 3 4\n",
    );
    let mut renderer = common::renderer();
    let (model, problems) = renderer.load_model_or_fallback(dir.join("quad.obj"));
    assert_eq!(problems.len(), 1, "{problems:?}");
    let magenta = magenta_share(&mut renderer, &model);
    assert!(magenta > 0.1, "only {magenta:.3} of the image is magenta");
    assert!(
        magenta < 0.9,
        "the checker's dark cells must show too ({magenta:.3} magenta)"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_mesh_costs_its_indexed_data_on_the_gpu() {
    //! Every mesh also uploaded an unindexed copy for the wireframe (3.4× its indexed data).
    let mut renderer = common::renderer();
    let sphere = MeshData::sphere(1.0, 64, 32);
    let (before, _) = renderer.gpu_bytes();
    if let Err(error) = renderer.add_mesh(&sphere, "sphere") {
        panic!("{error}");
    }
    let (after, _) = renderer.gpu_bytes();
    let indexed = (sphere.vertices.len() * size_of::<Vertex>() + sphere.indices.len() * 4) as u64;
    assert_eq!(
        after - before,
        indexed,
        "GPU bytes of one mesh against its indexed data"
    );
}
