//! Hot reload figures: the time of the swap itself, the latency from a new library file being
//! complete to the new code's first `on_update`, and memory growth per swap (each swap maps a
//! fresh copy of the library and never unmaps the old one).
//!
//! Needs the fixture libraries: `cargo build --workspace`, then
//! `cargo bench -p onyx-tests --bench hot_reload`.
//! Goal: swap < 50 ms after the file is complete; no entity or plugin state lost.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use onyx_runtime::plugins::plugin_search::library_file_name;
use onyx_runtime::world::PluginComponents;
use onyx_runtime::HeadlessHost;

const NAME: &str = "fixture_reload";
const SWAPS: u32 = 50;

/// The debug build of fixture `version` (benches run from target/release).
fn build(version: u32) -> PathBuf {
    let exe = std::env::current_exe().expect("own path");
    let target = exe.ancestors().nth(3).expect("target/release/deps/<bench>");
    let path = target
        .join("debug")
        .join(library_file_name(&format!("fixture-reload-v{version}")));
    assert!(
        path.is_file(),
        "{} is missing: run `cargo build --workspace` first",
        path.display()
    );
    path
}

fn version(host: &HeadlessHost) -> u64 {
    let (e, _) = host
        .find::<onyx_plugin_api::Name>("reloadable")
        .expect("entity");
    let blobs = host.get::<PluginComponents>(e).expect("components");
    let value: serde_json::Value =
        serde_json::from_slice(&blobs.0["fixture_reload.progress"].bytes).expect("json");
    value["version"].as_u64().expect("version")
}

fn resident_bytes() -> u64 {
    let statm = std::fs::read_to_string("/proc/self/statm").unwrap_or_default();
    let pages: u64 = statm
        .split_whitespace()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(0);
    pages * 4096
}

fn replace(source: &Path, target: &Path, staging: &Path) {
    std::fs::copy(source, staging).expect("copy");
    std::fs::rename(staging, target).expect("rename");
}

fn percentile(mut samples: Vec<Duration>, p: f64) -> Duration {
    samples.sort();
    samples[((samples.len() - 1) as f64 * p).round() as usize]
}

fn main() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join(library_file_name(NAME));
    let staging = dir.path().join("staging");
    std::fs::copy(build(1), &path).expect("copy v1");
    let mut host = HeadlessHost::new();
    host.load_plugin_file(&path).expect("loads");
    host.host_mut().set_hot_reload(true).expect("watcher");
    host.step(3);
    let entities = host.world().iter().count();

    // 1. The swap itself (manual reload): load the fresh copy, carry state, swap.
    let rss_before = resident_bytes();
    let mut swaps = Vec::new();
    for i in 0..SWAPS {
        replace(&build(2 - i % 2), &path, &staging);
        let start = Instant::now();
        host.host_mut().reload_plugin(NAME).expect("reload");
        swaps.push(start.elapsed());
        host.step(1);
    }
    let rss_after = resident_bytes();

    // 2. File complete → the new build's first on_update, through the file watcher, with
    //    frames run back to back.
    let mut latencies = Vec::new();
    for i in 0..20u32 {
        let next = 2 - (SWAPS + i) % 2;
        let current = version(&host);
        assert_ne!(current, u64::from(next));
        replace(&build(next), &path, &staging);
        let complete = Instant::now();
        while version(&host) != u64::from(next) {
            host.step(1);
            assert!(complete.elapsed() < Duration::from_secs(5), "no reload");
        }
        latencies.push(complete.elapsed());
    }
    assert_eq!(host.world().iter().count(), entities, "entities lost");

    println!(
        "== hot reload ({SWAPS} manual swaps, 20 watched swaps; fixture plugin, debug build) =="
    );
    println!(
        "swap (load fresh copy + save/load state + detach/attach): median {:.2?}, p95 {:.2?}",
        percentile(swaps.clone(), 0.5),
        percentile(swaps, 0.95)
    );
    println!(
        "file complete → new code's first on_update: median {:.1?}, p95 {:.1?} \
         (quiet period {:?} + swap; a 60 fps host adds up to one frame)   [goal < 50 ms]",
        percentile(latencies.clone(), 0.5),
        percentile(latencies, 0.95),
        onyx_runtime::plugins::library_watcher::RELOAD_QUIET_PERIOD,
    );
    let growth = rss_after.saturating_sub(rss_before) as f64 / f64::from(SWAPS);
    println!(
        "resident memory growth: {:.1} KiB per swap (library file {:.1} MiB; old images stay mapped)",
        growth / 1024.0,
        std::fs::metadata(build(1)).map(|m| m.len()).unwrap_or(0) as f64 / 1048576.0
    );
    println!("entities kept: {entities} of {entities}");
}
