//! The editor's cost per frame: CPU time of one host frame (host + editor plugin: its egui
//! frame with the hierarchy and the inspector open, tessellation, the meshes and input
//! crossing the plugin boundary) with 100, 1,000 and 10,000 entities, and 10,000 entities in a
//! scene graph (100 roots, 10 children each, 9 grandchildren each: 10,000 rows of a tree,
//! all expanded), next to the same host and world before the editor is loaded (the peer,
//! measured in the same process).
//!
//! Needs the release build of the editor:
//! `cargo build --release -p onyx-editor && cargo bench -p onyx-tests --bench editor`.
//! Goal (issue #7): < 2 ms per frame at 10,000 entities, host + editor.
//!
//! Each size gets one host whose world holds `n` named cubes (`Name`, `Transform` on a grid,
//! a cube `MeshRenderer`). Measured, as median and p95 of one `host.step(1)` (the headless
//! host advances a fixed frame time):
//! 1. the host alone, before the editor is loaded;
//! 2. the same host and world with the editor, after a click on the row "Entity 0" in the
//!    hierarchy opened the inspector on it (asserted: the inspector shows `Transform`);
//! 3. the editor's share, (2) - (1), and where the editor's time goes: the time spent inside
//!    its lifecycle calls per stage (the host's `StageTimer`, read from the diagnostics), the
//!    rest being the host's side of its GUI (input, meshes, textures).
//!
//! Nothing is painted (the host only paints for a window or a screenshot), and the AccessKit
//! tree, which the headless host turns on to find widgets, is off while measuring: a window
//! builds it only when a screen reader asks.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::{Entity, Material, MeshId, MeshRenderer, Name, Parent, Transform};
use onyx_runtime::plugins::plugin_search::library_file_name;
use onyx_runtime::{HeadlessHost, HostConfig};

/// Entities, and whether they form a tree (else a flat list).
const SIZES: [(usize, bool); 4] = [
    (100, false),
    (1_000, false),
    (10_000, false),
    (10_000, true),
];
/// The tree: roots, children per root, grandchildren per child (100 + 1,000 + 9,000).
const TREE: (usize, usize, usize) = (100, 10, 9);
const GOAL_MS: f64 = 2.0;
const FRAMES: usize = 300;
const WARM_UP: u32 = 10;

/// The release editor library (benches run from target/release/deps).
fn editor_library() -> PathBuf {
    let exe = std::env::current_exe().expect("own path");
    let release = exe.ancestors().nth(2).expect("target/release/deps/<bench>");
    let path = release.join(library_file_name("editor"));
    assert!(
        path.is_file(),
        "{} is missing: run `cargo build --release -p onyx-editor` first",
        path.display()
    );
    path
}

/// A host whose world holds `n` named cubes on a grid (the editor adds its own camera); in a
/// tree ([`TREE`]) when `tree`.
fn host_with_entities(n: usize, tree: bool, layout: &Path) -> HeadlessHost {
    let config = HostConfig::default().setting("editor", "layout", layout.display().to_string());
    let mut host = HeadlessHost::with_config(config);
    let side = (n as f64).sqrt().ceil() as usize;
    let (roots, children, grandchildren) = TREE;
    let mut spawned: Vec<hecs::Entity> = Vec::with_capacity(n);
    for i in 0..n {
        let at = Vec3::new((i % side) as f32 * 2.0, 0.5, (i / side) as f32 * 2.0);
        // In the tree: the roots first, then each root's children, then their children.
        let parent = if !tree || i < roots {
            None
        } else if i < roots + roots * children {
            Some(spawned[(i - roots) / children])
        } else {
            Some(spawned[roots + (i - roots - roots * children) / grandchildren])
        };
        let world = host.host_mut().world_mut();
        let e = world.spawn((
            Name::new(format!("Entity {i}")),
            Transform::from_translation(at),
            MeshRenderer::new(MeshId::CUBE).with_material(Material::color(0.8, 0.8, 0.8)),
        ));
        if let Some(p) = parent {
            let _ = world.insert_one(e, Parent(Entity::from_bits(p.to_bits().get())));
        }
        spawned.push(e);
    }
    host
}

/// One peer's figures: one `host.step(1)`, ms.
struct Frames {
    median: f64,
    p95: f64,
    /// Mean time per frame inside the editor's lifecycle calls, per stage (empty without it).
    editor_stages: BTreeMap<String, f64>,
}

fn measure(host: &mut HeadlessHost) -> Frames {
    host.host_mut().gui_mut().set_accesskit(false);
    host.step(WARM_UP);
    let mut samples = Vec::with_capacity(FRAMES);
    let mut editor_stages = BTreeMap::new();
    for _ in 0..FRAMES {
        let start = Instant::now();
        host.step(1);
        samples.push(start.elapsed().as_secs_f64() * 1e3);
        let diagnostics = host.host().diagnostics();
        for timing in diagnostics.plugins.iter().filter(|p| p.plugin == "editor") {
            for stage in &timing.stages {
                *editor_stages.entry(stage.stage.clone()).or_insert(0.0) +=
                    stage.ms / FRAMES as f64;
            }
        }
    }
    samples.sort_by(f64::total_cmp);
    Frames {
        median: samples[samples.len() / 2],
        p95: samples[((samples.len() - 1) as f64 * 0.95).round() as usize],
        editor_stages,
    }
}

fn main() {
    let library = editor_library();
    let dir = tempfile::tempdir().expect("temp dir");
    let layout = dir.path().join("layout.json");

    let mut rows = Vec::new();
    for (n, tree) in SIZES {
        let mut host = host_with_entities(n, tree, &layout);
        let alone = measure(&mut host);

        host.host_mut().gui_mut().set_accesskit(true);
        host.load_plugin_file(&library).expect("the editor loads");
        host.step(3);
        // Open the inspector on one entity, as a person would: click its hierarchy row.
        assert!(
            host.click_widget("Entity 0"),
            "the hierarchy lists the entities"
        );
        host.step(2);
        assert!(
            host.find_widget("Transform").is_some() && host.find_widget("MeshRenderer").is_some(),
            "the inspector shows the selected entity"
        );
        let with = measure(&mut host);
        rows.push((n, tree, alone, with));
    }

    println!(
        "== editor cost per frame (CPU, one host.step(1), median / p95 of {FRAMES} frames; \
         hierarchy + inspector open, AccessKit off) =="
    );
    println!(
        "{:>11} {:>20} {:>20} {:>12}   inside the editor's calls (mean ms/frame)",
        "entities", "host alone ms", "host + editor ms", "editor ms"
    );
    for (n, tree, alone, with) in &rows {
        let n = format!("{n}{}", if *tree { " tree" } else { "" });
        let stages: Vec<String> = with
            .editor_stages
            .iter()
            .map(|(stage, ms)| format!("{stage} {ms:.3}"))
            .collect();
        println!(
            "{n:>11} {:>9.3} / {:<8.3} {:>9.3} / {:<8.3} {:>12.3}   {}",
            alone.median,
            alone.p95,
            with.median,
            with.p95,
            with.median - alone.median,
            stages.join(", ")
        );
    }
    let largest = rows.iter().map(|(n, ..)| *n).max().unwrap_or(0);
    let verdict = if rows
        .iter()
        .filter(|(n, ..)| *n == largest)
        .all(|(.., with)| with.median < GOAL_MS)
    {
        "met"
    } else {
        "NOT met"
    };
    for (n, tree, alone, with) in &rows {
        let shape = if *tree { "in a tree" } else { "flat" };
        println!(
            "{n} entities ({shape}): host alone {:.3} ms, host + editor {:.3} ms (editor {:.3} ms); \
             goal < {GOAL_MS} ms at {largest}: {verdict}",
            alone.median,
            with.median,
            with.median - alone.median,
        );
    }
}
