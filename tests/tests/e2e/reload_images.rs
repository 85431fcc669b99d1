//! What a swap leaves in memory: an old build's image is unmapped when nothing from it can
//! run again (`fixture_reload`, which starts no thread), and stays mapped, safely, while
//! something of it can — a thread left running, a thread-local destructor pending on a
//! thread that still runs (`fixture_threads`). A plugin that stops its thread in
//! `on_detach` swaps and unloads cleanly.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use onyx_runtime::plugins::plugin_search::library_file_name;
use onyx_runtime::plugins::{ImageFate, PluginOrigin};
use onyx_runtime::{HeadlessHost, HostConfig, PluginStatus};
use onyx_tests::plugin_library;

const NAME: &str = "fixture_threads";

/// These tests count the process's ticker threads: they take turns.
static TURN: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn turn() -> std::sync::MutexGuard<'static, ()> {
    TURN.lock().unwrap_or_else(|e| e.into_inner())
}

/// Whether the copy at `path` is mapped in this process (`/proc/self/maps` lists a deleted
/// copy as `path (deleted)`).
fn mapped(path: &Path) -> bool {
    let maps = std::fs::read_to_string("/proc/self/maps").expect("Linux lists mappings");
    let path = path.display().to_string();
    maps.lines().any(|line| {
        line.split_once('/')
            .is_some_and(|(_, rest)| format!("/{rest}").trim_end_matches(" (deleted)") == path)
    })
}

/// Waits (up to 5 s) until `count` threads of this process are called `name`: a thread
/// names itself once it starts, a stopped one is gone once joined.
fn wait_for_threads(name: &str, count: usize) {
    let start = Instant::now();
    while threads_named(name) != count {
        assert!(
            start.elapsed() < Duration::from_secs(5),
            "{} threads named `{name}`, not {count}",
            threads_named(name)
        );
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// How many threads of this process are called `name`.
fn threads_named(name: &str) -> usize {
    let Ok(tasks) = std::fs::read_dir("/proc/self/task") else {
        return 0;
    };
    tasks
        .flatten()
        .filter(|t| {
            std::fs::read_to_string(t.path().join("comm")).is_ok_and(|c| c.trim_end() == name)
        })
        .count()
}

fn loaded_from(host: &HeadlessHost) -> PathBuf {
    match host.host().plugin(NAME).expect("loaded").origin() {
        PluginOrigin::Library { loaded_from, .. } => loaded_from.clone(),
        other => panic!("{other:?}"),
    }
}

fn ticks(host: &HeadlessHost) -> u64 {
    let (e, _) = host
        .find::<onyx_plugin_api::Name>("threads")
        .expect("the plugin made its entity");
    let blobs = host
        .get::<onyx_runtime::world::PluginComponents>(e)
        .expect("it published");
    let value: serde_json::Value =
        serde_json::from_slice(&blobs.0["fixture_threads.ticks"].bytes).expect("JSON");
    value["ticks"].as_u64().expect("a count")
}

/// Steps until the ticker of the running build has counted, or fails.
fn wait_for_ticks(host: &mut HeadlessHost) {
    let start = Instant::now();
    loop {
        host.step(1);
        if ticks(host) > 0 {
            return;
        }
        assert!(
            start.elapsed() < Duration::from_secs(5),
            "the ticker never ticked"
        );
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// A host running `fixture_threads` from a copy in a temp dir, with `settings`.
fn running(settings: &[(&str, &str)]) -> (HeadlessHost, tempfile::TempDir) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(library_file_name(NAME));
    std::fs::copy(plugin_library("fixture-threads"), &path).unwrap();
    let mut config = HostConfig::default();
    for (key, value) in settings {
        config = config.setting(NAME, *key, *value);
    }
    let mut host = HeadlessHost::with_config(config);
    host.load_plugin_file(&path).unwrap();
    wait_for_ticks(&mut host);
    (host, dir)
}

fn old_image(host: &HeadlessHost) -> ImageFate {
    host.host()
        .last_reload()
        .expect("a swap happened")
        .old_image
        .clone()
}

/// A plugin that starts a thread in `on_attach` and stops it in `on_detach`, as the README
/// asks: across swaps and the unload, exactly one ticker runs (the old build's is gone when
/// the swap returns) and the plugin keeps running. Its old images stay mapped, and the host
/// says so truthfully: Rust's std registers a thread-local destructor on the thread that
/// calls `spawn` (its list of spawn hooks), here the host's, and glibc keeps the image
/// until that thread ends.
#[test]
fn a_build_that_stops_its_thread_on_detach_swaps_and_unloads_cleanly() {
    let _turn = turn();
    let (mut host, _dir) = running(&[]);
    let before = threads_named("fixture-ticker");
    assert!(before >= 1, "the ticker does not run");
    for swap in 1..=3 {
        let old = loaded_from(&host);
        assert!(mapped(&old), "swap {swap}: the running build is not mapped");
        host.host_mut().reload_plugin(NAME).unwrap();
        assert_eq!(old_image(&host), ImageFate::Pinned, "swap {swap}");
        assert!(mapped(&old), "swap {swap}: reported pinned but gone");
        assert!(mapped(&loaded_from(&host)));
        // The old build's ticker ended in on_detach; the new build started its own.
        wait_for_threads("fixture-ticker", before);
        wait_for_ticks(&mut host);
    }
    assert_eq!(host.plugin_status(NAME), Some(&PluginStatus::Running));
    assert!(
        host.host().incidents().is_empty(),
        "{:?}",
        host.host().incidents()
    );
    // Unloading the plugin stops its last ticker.
    assert!(host.host_mut().unload_plugin(NAME));
    wait_for_threads("fixture-ticker", before - 1);
}

#[test]
fn a_thread_left_running_keeps_the_old_image_mapped_and_running() {
    let _turn = turn();
    let (mut host, _dir) = running(&[("leave_thread", "1")]);
    let before = threads_named("fixture-ticker");
    let old = loaded_from(&host);
    host.host_mut().reload_plugin(NAME).unwrap();
    assert_eq!(old_image(&host), ImageFate::Pinned);
    assert!(
        mapped(&old),
        "the old build's image went while its thread runs"
    );
    // Both tickers run: the old one in its image, which is still there.
    wait_for_threads("fixture-ticker", before + 1);
    std::thread::sleep(Duration::from_millis(20));
    wait_for_ticks(&mut host);
    assert_eq!(host.plugin_status(NAME), Some(&PluginStatus::Running));
}

#[test]
fn a_thread_local_filled_on_the_host_thread_keeps_the_image_until_that_thread_ends() {
    // The host runs on a thread of its own, which then ends: the thread-local's destructor
    // runs from the old image at that thread's exit, so the image must still be there.
    let _turn = turn();
    let old = std::thread::spawn(|| {
        let (mut host, dir) = running(&[("thread_local", "1")]);
        host.step(2);
        let old = loaded_from(&host);
        host.host_mut().reload_plugin(NAME).unwrap();
        assert_eq!(old_image(&host), ImageFate::Pinned);
        assert!(mapped(&old));
        host.host_mut().shutdown();
        drop((host, dir));
        old
    })
    .join()
    .expect("the host thread ended without a crash");
    // Still alive here: the destructor ran from a mapped image.
    assert!(old.is_absolute());
}

/// `fixture_reload` starts no thread and keeps no thread-local: each old build's image is
/// unmapped by the swap that replaces it, and the last one by the unload.
#[test]
fn an_old_build_that_left_nothing_running_is_unmapped() {
    const RELOAD: &str = "fixture_reload";
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(library_file_name(RELOAD));
    std::fs::copy(plugin_library("fixture-reload-v1"), &path).unwrap();
    let mut host = HeadlessHost::new();
    host.load_plugin_file(&path).unwrap();
    host.step(2);
    let copy = |host: &HeadlessHost| match host.host().plugin(RELOAD).expect("loaded").origin() {
        PluginOrigin::Library { loaded_from, .. } => loaded_from.clone(),
        other => panic!("{other:?}"),
    };
    for swap in 1..=4u32 {
        let old = copy(&host);
        assert!(mapped(&old), "swap {swap}: the running build is not mapped");
        let staging = path.with_extension("staging");
        let version = 1 + swap % 2;
        std::fs::copy(
            plugin_library(&format!("fixture-reload-v{version}")),
            &staging,
        )
        .unwrap();
        std::fs::rename(&staging, &path).unwrap();
        host.host_mut().reload_plugin(RELOAD).unwrap();
        assert_eq!(old_image(&host), ImageFate::Unmapped, "swap {swap}");
        assert!(
            !mapped(&old),
            "swap {swap}: `{}` is still mapped",
            old.display()
        );
        host.step(2);
    }
    let last = copy(&host);
    assert!(host.host_mut().unload_plugin(RELOAD));
    assert!(
        !mapped(&last),
        "the unloaded plugin's image is still mapped"
    );
}

/// An automatic reload (the file watcher, at the start of a frame) hands the old image back
/// at the end of that frame, off the swap: once the frame that swapped has returned, the old
/// build is unmapped and the swap's report says so.
#[test]
fn a_watched_swap_unmaps_the_old_image_by_the_end_of_its_frame() {
    const RELOAD: &str = "fixture_reload";
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(library_file_name(RELOAD));
    std::fs::copy(plugin_library("fixture-reload-v1"), &path).unwrap();
    let mut host = HeadlessHost::new();
    host.load_plugin_file(&path).unwrap();
    host.host_mut().set_hot_reload(true).unwrap();
    host.step(2);
    let copy = |host: &HeadlessHost| match host.host().plugin(RELOAD).expect("loaded").origin() {
        PluginOrigin::Library { loaded_from, .. } => loaded_from.clone(),
        other => panic!("{other:?}"),
    };
    let reloads = |host: &HeadlessHost| host.host().plugin(RELOAD).expect("loaded").reloads();
    for swap in 1..=2u32 {
        let old = copy(&host);
        let staging = path.with_extension("staging");
        std::fs::copy(
            plugin_library(&format!("fixture-reload-v{}", 1 + swap % 2)),
            &staging,
        )
        .unwrap();
        std::fs::rename(&staging, &path).unwrap();
        let started = Instant::now();
        while reloads(&host) < swap {
            host.step(1);
            assert!(started.elapsed() < Duration::from_secs(10), "no reload");
        }
        assert_eq!(old_image(&host), ImageFate::Unmapped, "swap {swap}");
        assert!(!mapped(&old), "swap {swap}: the old image is still mapped");
        assert!(
            mapped(&copy(&host)),
            "swap {swap}: the new build is not mapped"
        );
    }
    assert_eq!(host.plugin_status(RELOAD), Some(&PluginStatus::Running));
}
