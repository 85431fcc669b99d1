//! Import settings for a glTF file imported as a node tree: scale and up axis apply once, at
//! the imported root (node positions scale and turn with the meshes, the model stays one
//! piece), normals reach every mesh. Real Khronos samples from `../shared/fixtures/gltf/`;
//! skips, saying so, when they are absent.

mod common;

use std::path::{Path, PathBuf};

use onyx_plugin_api::__ffi::with_ctx;
use onyx_plugin_api::glam::{Quat, Vec3};
use onyx_plugin_api::{Entity, MeshRenderer, Name, Parent};
use onyx_render::{ImportSettings, NormalMode, UpAxis};
use onyx_runtime::HeadlessHost;

/// OrientationTest: a dozen meshes on translated, rotated nodes around the origin.
fn orientation_test() -> Option<PathBuf> {
    let path = common::gltf_samples()?.join("OrientationTest/glTF-Binary/OrientationTest.glb");
    if path.is_file() {
        Some(path)
    } else {
        eprintln!("skipped: {} is absent", path.display());
        None
    }
}

/// One node of the imported tree: its name, world translation and rotation.
#[derive(Debug)]
struct Node {
    name: String,
    translation: Vec3,
    rotation: Quat,
}

/// What a spawned import looks like: every node (by name) and the world box around every
/// mesh (each mesh's local bounds, as the tools read its geometry, through its world pose).
struct Imported {
    nodes: Vec<Node>,
    min: Vec3,
    max: Vec3,
}

fn imported(host: &mut HeadlessHost) -> Imported {
    let mut entities: Vec<(Entity, String)> = host
        .world()
        .query::<(hecs::Entity, &Name, &Parent)>()
        .iter()
        .map(|(e, name, _)| (Entity::from_bits(e.to_bits().get()), name.0.clone()))
        .collect();
    entities.sort_by(|a, b| a.1.cmp(&b.1));
    let mut nodes = Vec::new();
    let (mut min, mut max) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    for (entity, name) in entities {
        let pose = host
            .host()
            .world_pose(entity)
            .unwrap_or_else(|| panic!("{name} has no world pose"))
            .0;
        let (_, rotation, translation) = pose.to_scale_rotation_translation();
        nodes.push(Node {
            name: name.clone(),
            translation,
            rotation,
        });
        if host.get::<MeshRenderer>(entity).is_none() {
            continue;
        }
        let bounds = host
            .host_mut()
            .with_services("test", |s| with_ctx(s, |ctx| ctx.local_bounds(entity)))
            .unwrap_or_else(|| panic!("{name}'s mesh has no bounds"));
        for corner in 0..8 {
            let local = Vec3::new(
                if corner & 1 == 0 {
                    bounds.min.x
                } else {
                    bounds.max.x
                },
                if corner & 2 == 0 {
                    bounds.min.y
                } else {
                    bounds.max.y
                },
                if corner & 4 == 0 {
                    bounds.min.z
                } else {
                    bounds.max.z
                },
            );
            let world = pose.transform_point3(local);
            min = min.min(world);
            max = max.max(world);
        }
    }
    assert!(nodes.len() > 5, "too few nodes imported: {nodes:?}");
    Imported { nodes, min, max }
}

/// `path` opened as the scene (`onyx run --scene FILE` with the command line's settings).
fn opened(path: &Path, settings: ImportSettings) -> (HeadlessHost, Imported) {
    let mut host = HeadlessHost::new();
    host.host_mut().set_import_settings(path, settings);
    host.load_scene(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let imported = imported(&mut host);
    (host, imported)
}

fn scaled(scale: f32) -> ImportSettings {
    ImportSettings {
        scale,
        ..ImportSettings::default()
    }
}

#[test]
fn a_scaled_node_tree_scales_as_one_piece() {
    let Some(path) = orientation_test() else {
        return;
    };
    let (_, plain) = opened(&path, ImportSettings::default());
    let (_, double) = opened(&path, scaled(2.0));
    assert_eq!(plain.nodes.len(), double.nodes.len());
    let mut spread = 0.0f32;
    for (a, b) in plain.nodes.iter().zip(&double.nodes) {
        assert_eq!(a.name, b.name);
        // A power of two scales every product and sum of the chain exactly.
        assert_eq!(
            b.translation,
            a.translation * 2.0,
            "{}: at {} unscaled, {} scaled 2x",
            a.name,
            a.translation,
            b.translation
        );
        assert!(b.rotation.abs_diff_eq(a.rotation, 1e-6), "{}", a.name);
        spread = spread.max(a.translation.length());
    }
    assert!(spread > 1.0, "the sample's nodes are not spread apart");
    // Each piece is drawn at scale 1 in its node's space: the world box doubles (a piece
    // scaled again in its own space would make it 4x).
    assert!(
        double.min.abs_diff_eq(plain.min * 2.0, 1e-4)
            && double.max.abs_diff_eq(plain.max * 2.0, 1e-4),
        "world bounds {}..{} scaled, {}..{} unscaled",
        double.min,
        double.max,
        plain.min,
        plain.max
    );
}

#[test]
fn a_z_up_node_tree_is_turned_to_y_up_as_one_piece() {
    let Some(path) = orientation_test() else {
        return;
    };
    let (_, plain) = opened(&path, ImportSettings::default());
    let z_up = ImportSettings {
        up_axis: UpAxis::Z,
        ..ImportSettings::default()
    };
    let (_, turned) = opened(&path, z_up);
    let turn = Quat::from_rotation_x(-std::f32::consts::FRAC_PI_2);
    for (a, b) in plain.nodes.iter().zip(&turned.nodes) {
        let [x, y, z] = UpAxis::Z.to_y_up(a.translation.to_array());
        assert!(
            b.translation.abs_diff_eq(Vec3::new(x, y, z), 1e-4),
            "{}: at {}, turned to {} (expected ({x}, {y}, {z}))",
            a.name,
            a.translation,
            b.translation
        );
        assert!(
            (turn * a.rotation).dot(b.rotation).abs() > 1.0 - 1e-5,
            "{}: rotation {} not turned from {}",
            a.name,
            b.rotation,
            a.rotation
        );
    }
    // The file's +Z is now +Y, its +Y is -Z: (x, y, z) -> (x, z, -y).
    let expected_min = Vec3::new(plain.min.x, plain.min.z, -plain.max.y);
    let expected_max = Vec3::new(plain.max.x, plain.max.z, -plain.min.y);
    assert!(
        turned.min.abs_diff_eq(expected_min, 1e-4) && turned.max.abs_diff_eq(expected_max, 1e-4),
        "world bounds {}..{}, expected {expected_min}..{expected_max}",
        turned.min,
        turned.max
    );
}

#[test]
fn the_normals_setting_reaches_every_mesh_without_its_scale() {
    let Some(path) = orientation_test() else {
        return;
    };
    let settings = ImportSettings {
        scale: 3.0,
        up_axis: UpAxis::Z,
        normals: NormalMode::Flat,
    };
    let (host, _) = opened(&path, settings);
    let mut pieces = 0;
    for renderer in host.world().query::<&MeshRenderer>().iter() {
        let assets = host.host().assets();
        let piece = assets
            .mesh_path(renderer.mesh)
            .unwrap_or_else(|| panic!("mesh {:?} has no path", renderer.mesh));
        assert!(
            piece.to_string_lossy().contains("#mesh/"),
            "{}",
            piece.display()
        );
        // Each piece generates its normals as asked, in its node's own space.
        assert_eq!(
            assets.import_settings(piece),
            ImportSettings {
                normals: NormalMode::Flat,
                ..ImportSettings::default()
            },
            "{}",
            piece.display()
        );
        pieces += 1;
    }
    assert!(pieces > 5, "only {pieces} meshes");
}

#[test]
fn an_import_into_a_scene_takes_its_imports_entry_and_saves_once_scaled() {
    let Some(path) = orientation_test() else {
        return;
    };
    let (_, plain) = opened(&path, ImportSettings::default());
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let scene = dir.path().join("scene.ron");
    std::fs::write(
        &scene,
        format!(
            "(version: 3, imports: {{ \"{}\": (scale: Some(2.0)) }}, entities: [])",
            path.display()
        ),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let mut host = HeadlessHost::new();
    host.load_scene(&scene).unwrap_or_else(|e| panic!("{e}"));
    let text = path.to_string_lossy().into_owned();
    host.host_mut()
        .with_services("test", |s| with_ctx(s, |ctx| ctx.import_gltf(&text)))
        .unwrap_or_else(|e| panic!("{e}"));
    let check = |imported: &Imported, what: &str| {
        for (a, b) in plain.nodes.iter().zip(&imported.nodes) {
            assert_eq!(b.translation, a.translation * 2.0, "{what}: {}", a.name);
        }
        assert!(
            imported.max.abs_diff_eq(plain.max * 2.0, 1e-4),
            "{what}: world bounds reach {}, unscaled {}",
            imported.max,
            plain.max
        );
    };
    check(&imported(&mut host), "imported");
    // Saved and opened again: the root keeps its scale, the pieces take none of their own.
    let saved = dir.path().join("saved.ron");
    host.host()
        .save_scene(&saved)
        .unwrap_or_else(|e| panic!("{e}"));
    let mut reopened = HeadlessHost::new();
    reopened
        .load_scene(&saved)
        .unwrap_or_else(|e| panic!("{e}"));
    check(&imported(&mut reopened), "saved and reopened");
}
