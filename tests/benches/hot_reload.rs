//! Hot reload figures: the time of the swap itself and where it goes (read, check, copy,
//! map, state, attach, drop, unload), the latency from a new library file being complete to
//! the new code's first `on_update`, what one image holds in memory, and resident memory
//! growth per swap over 200 swaps (old images are unmapped when nothing from them can run).
//!
//! Needs the fixture libraries: `cargo build --workspace`, then
//! `cargo bench -p onyx-tests --bench hot_reload`.
//! Goals: swap median < 15 ms and p95 < 25 ms file complete → new code; < 1 MiB growth per
//! swap; no entity or plugin state lost.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use onyx_runtime::plugins::plugin_search::library_file_name;
use onyx_runtime::plugins::{ImageFate, PluginOrigin, ReloadReport};
use onyx_runtime::world::PluginComponents;
use onyx_runtime::HeadlessHost;

const NAME: &str = "fixture_reload";
const SWAPS: u32 = 200;
/// Swaps before memory is measured: the first ones fill caches that stay (allocator arenas,
/// abi_stable's layout cache).
const WARM_UP: u32 = 10;
const WATCHED_SWAPS: u32 = 40;

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

fn progress(host: &HeadlessHost) -> serde_json::Value {
    let (e, _) = host
        .find::<onyx_plugin_api::Name>("reloadable")
        .expect("entity");
    let blobs = host.get::<PluginComponents>(e).expect("components");
    serde_json::from_slice(&blobs.0["fixture_reload.progress"].bytes).expect("json")
}

fn version(host: &HeadlessHost) -> u64 {
    progress(host)["version"].as_u64().expect("version")
}

fn now_us() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_micros() as u64)
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

fn median_of(reports: &[ReloadReport], stage: impl Fn(&ReloadReport) -> Duration) -> Duration {
    percentile(reports.iter().map(stage).collect(), 0.5)
}

/// (size, resident, private dirty) in KiB of the mappings of `path` (`/proc/self/smaps`).
fn image_memory(path: &Path) -> (u64, u64, u64) {
    let smaps = std::fs::read_to_string("/proc/self/smaps").unwrap_or_default();
    let name = path.display().to_string();
    let (mut size, mut rss, mut dirty) = (0, 0, 0);
    let mut inside = false;
    for line in smaps.lines() {
        let mut fields = line.split_whitespace();
        let first = fields.next().unwrap_or_default();
        if first.contains('-') && !first.ends_with(':') {
            inside = line.contains(&name);
            continue;
        }
        if !inside {
            continue;
        }
        let kib: u64 = fields.next().and_then(|v| v.parse().ok()).unwrap_or(0);
        match first {
            "Size:" => size += kib,
            "Rss:" => rss += kib,
            "Private_Dirty:" => dirty += kib,
            _ => {}
        }
    }
    (size, rss, dirty)
}

fn loaded_from(host: &HeadlessHost) -> PathBuf {
    match host.host().plugin(NAME).map(|p| p.origin()) {
        Some(PluginOrigin::Library { loaded_from, .. }) => loaded_from.clone(),
        _ => PathBuf::new(),
    }
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
    let (image_size, image_rss, image_dirty) = image_memory(&loaded_from(&host));

    // 1. The swap itself (manual reload): read, check, copy, map, carry state, swap, unload.
    let mut swaps = Vec::new();
    let mut reports = Vec::new();
    let mut rss_before = 0;
    for i in 0..WARM_UP + SWAPS {
        if i == WARM_UP {
            rss_before = resident_bytes();
        }
        replace(&build(2 - i % 2), &path, &staging);
        let start = Instant::now();
        host.host_mut().reload_plugin(NAME).expect("reload");
        swaps.push(start.elapsed());
        reports.push(host.host().last_reload().expect("a report").clone());
        host.step(1);
    }
    let rss_after = resident_bytes();
    let swaps = swaps.split_off(WARM_UP as usize);

    // 2. File complete → the new build's first on_update, through the file watcher, with
    //    frames run back to back.
    let mut latencies = Vec::new();
    let mut frame_ends = Vec::new();
    for i in 0..WATCHED_SWAPS {
        let next = 2 - (WARM_UP + SWAPS + i) % 2;
        let current = version(&host);
        assert_ne!(current, u64::from(next));
        replace(&build(next), &path, &staging);
        let (complete, complete_us) = (Instant::now(), now_us());
        while version(&host) != u64::from(next) {
            host.step(1);
            assert!(complete.elapsed() < Duration::from_secs(5), "no reload");
        }
        frame_ends.push(complete.elapsed());
        let ran_at = progress(&host)["updated_at_us"].as_u64().expect("a time");
        latencies.push(Duration::from_micros(ran_at.saturating_sub(complete_us)));
    }
    assert_eq!(host.world().iter().count(), entities, "entities lost");

    println!(
        "== hot reload ({SWAPS} manual swaps after {WARM_UP}, {WATCHED_SWAPS} watched swaps; \
         fixture plugin, debug build) =="
    );
    println!(
        "swap (read + check + copy + map + state + detach/attach + drop + unload): median \
         {:.2?}, p95 {:.2?}",
        percentile(swaps.clone(), 0.5),
        percentile(swaps, 0.95)
    );
    println!(
        "  median per stage: read {:.2?}, check {:.2?}, copy {:.2?}, map {:.2?}, construct \
         {:.2?}, state {:.2?} ({} bytes), detach/attach {:.2?}, drop {:.2?}, unload {:.2?}",
        median_of(&reports, |r| r.load.read),
        median_of(&reports, |r| r.load.check),
        median_of(&reports, |r| r.load.copy),
        median_of(&reports, |r| r.load.map),
        median_of(&reports, |r| r.construct),
        median_of(&reports, |r| r.state),
        reports.last().map_or(0, |r| r.state_bytes),
        median_of(&reports, |r| r.attach),
        median_of(&reports, |r| r.drop),
        median_of(&reports, |r| r.unload),
    );
    println!(
        "file complete → new code's first on_update: median {:.1?}, p95 {:.1?} \
         (frames back to back)   [goal median < 15 ms, p95 < 25 ms]",
        percentile(latencies.clone(), 0.5),
        percentile(latencies, 0.95),
    );
    println!(
        "file complete → the end of the frame that swapped (its GUI pass included): median \
         {:.1?}, p95 {:.1?}",
        percentile(frame_ends.clone(), 0.5),
        percentile(frame_ends, 0.95),
    );
    let unmapped = reports
        .iter()
        .filter(|r| r.old_image == ImageFate::Unmapped)
        .count();
    let other: Vec<String> = reports
        .iter()
        .filter(|r| r.old_image != ImageFate::Unmapped)
        .map(|r| r.old_image.to_string())
        .take(1)
        .collect();
    println!(
        "one image mapped: {:.1} MiB of address space, {:.1} MiB resident after loading, \
         {:.0} KiB of it private (relocated data); old images unmapped: {unmapped} of {} {}",
        image_size as f64 / 1024.0,
        image_rss as f64 / 1024.0,
        image_dirty as f64,
        reports.len(),
        other
            .first()
            .map(|o| format!("(others: {o})"))
            .unwrap_or_default()
    );
    let growth = rss_after.saturating_sub(rss_before) as f64 / f64::from(SWAPS);
    println!(
        "resident memory growth: {:.1} KiB per swap over {SWAPS} swaps (library file {:.1} \
         MiB)   [goal < 1 MiB]",
        growth / 1024.0,
        std::fs::metadata(build(1)).map(|m| m.len()).unwrap_or(0) as f64 / 1048576.0
    );
    println!("entities kept: {entities} of {entities}");
}
