//! The editor's cost per frame: CPU time of one host frame (host + editor plugin: its egui
//! frame with the hierarchy and the inspector open, tessellation, the meshes and input
//! crossing the plugin boundary) with 100, 1,000 and 10,000 entities, next to the same host
//! and world without the editor (the peer, measured in the same process).
//!
//! Needs the release build of the editor:
//! `cargo build --release -p onyx-editor && cargo bench -p onyx-tests --bench editor`.
//! Goal: the editor adds < 2 ms per frame at 10,000 entities.
//!
//! Nothing is painted (the host only paints for a window or a screenshot), and the AccessKit
//! tree, which tests use to find widgets, is off while measuring: a window builds it only when
//! a screen reader asks.

use std::path::{Path, PathBuf};
use std::time::Instant;

use onyx_plugin_api::glam::Vec3;
use onyx_plugin_api::{Material, MeshId, MeshRenderer, Name, Transform};
use onyx_runtime::plugins::plugin_search::library_file_name;
use onyx_runtime::{HeadlessHost, HostConfig};

const SIZES: [usize; 3] = [100, 1_000, 10_000];
const GOAL_MS: f64 = 2.0;

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

/// A host whose world holds `n` named cubes on a grid (the editor's own camera comes on top).
fn host_with_entities(n: usize, layout_dir: &Path) -> HeadlessHost {
    let config = HostConfig::default().setting(
        "editor",
        "layout",
        layout_dir.join("layout.json").display().to_string(),
    );
    let mut host = HeadlessHost::with_config(config);
    let side = (n as f64).sqrt().ceil() as usize;
    for i in 0..n {
        let at = Vec3::new((i % side) as f32 * 2.0, 0.5, (i / side) as f32 * 2.0);
        host.host_mut().world_mut().spawn((
            Name::new(format!("Entity {i}")),
            Transform::from_translation(at),
            MeshRenderer::new(MeshId::CUBE).with_material(Material::color(0.8, 0.8, 0.8)),
        ));
    }
    host
}

/// Median and 95th percentile of one `host.step(1)`, ms.
fn frame_ms(host: &mut HeadlessHost, frames: usize) -> (f64, f64) {
    host.step(10);
    let mut samples: Vec<f64> = (0..frames)
        .map(|_| {
            let start = Instant::now();
            host.step(1);
            start.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    (
        samples[samples.len() / 2],
        samples[(samples.len() * 95 / 100).min(samples.len() - 1)],
    )
}

fn main() {
    let library = editor_library();
    let dir = std::env::temp_dir().join(format!("onyx-editor-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    println!("== editor cost per frame (host + editor, CPU, median / p95 of one frame) ==");
    println!(
        "{:>8} {:>22} {:>22} {:>14}",
        "entities", "host alone ms", "host + editor ms", "editor ms"
    );
    let mut at_largest = 0.0;
    for n in SIZES {
        let frames = if n >= 10_000 { 120 } else { 300 };

        let mut alone = host_with_entities(n, &dir);
        alone.host_mut().gui_mut().set_accesskit(false);
        let (alone_ms, alone_p95) = frame_ms(&mut alone, frames);
        drop(alone);

        let mut host = host_with_entities(n, &dir);
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
        host.host_mut().gui_mut().set_accesskit(false);
        let (with_ms, with_p95) = frame_ms(&mut host, frames);
        let editor_ms = with_ms - alone_ms;
        println!(
            "{n:>8} {:>10.3} / {:<9.3} {:>10.3} / {:<9.3} {:>14.3}",
            alone_ms, alone_p95, with_ms, with_p95, editor_ms
        );
        at_largest = editor_ms;
    }
    let _ = std::fs::remove_dir_all(&dir);
    println!(
        "summary: the editor adds {at_largest:.3} ms per frame at {} entities (goal < {GOAL_MS} ms): {}",
        SIZES[SIZES.len() - 1],
        if at_largest < GOAL_MS { "met" } else { "NOT met" }
    );
}
