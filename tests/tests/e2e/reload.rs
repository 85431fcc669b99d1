//! Hot reload with real libraries: a plugin file is replaced while the host runs; the new
//! build takes over with the old one's state, every entity stays, and a bad build never
//! replaces a good one.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use onyx_plugin_api::{Ctx, Flow, Plugin};
use onyx_runtime::plugins::Stage;
use onyx_runtime::{HeadlessHost, HostConfig, PluginStatus, ReloadError};
use onyx_tests::{entries, journal, plugin_library, Recorder};
use serde::Deserialize;

const NAME: &str = "fixture_reload";

#[derive(Debug, Deserialize, PartialEq)]
struct Progress {
    version: u32,
    total: u64,
    reloads_seen: u32,
}

/// A `static` of `fixture_reload`: how often `on_attach` ran in the running image.
#[derive(Debug, Deserialize)]
struct ImageStatics {
    attaches_in_image: u32,
}

/// What `fixture_reload` counted of `fixture_peer`'s pings.
#[derive(Debug, Deserialize, PartialEq)]
struct PingCount {
    pings: u64,
    ping_gaps: u64,
}

/// What `fixture_peer` saw of `fixture_reload`'s answers.
#[derive(Debug, Deserialize)]
struct PeerProgress {
    sent: u64,
    pongs: u64,
    last_pong: u64,
    gaps: u64,
    versions: Vec<u32>,
}

fn component<T: serde::de::DeserializeOwned>(host: &HeadlessHost, entity: &str, key: &str) -> T {
    let (e, _) = host
        .find::<onyx_plugin_api::Name>(entity)
        .unwrap_or_else(|| panic!("no entity `{entity}`"));
    let blobs = host
        .get::<onyx_runtime::world::PluginComponents>(e)
        .unwrap();
    serde_json::from_slice(&blobs.0[key].bytes).unwrap()
}

fn progress(host: &HeadlessHost) -> Progress {
    let (e, _) = host
        .find::<onyx_plugin_api::Name>("reloadable")
        .expect("the plugin made its entity");
    let blobs = host
        .get::<onyx_runtime::world::PluginComponents>(e)
        .unwrap();
    serde_json::from_slice(&blobs.0["fixture_reload.progress"].bytes).unwrap()
}

fn build(version: u32) -> PathBuf {
    plugin_library(&format!("fixture-reload-v{version}"))
}

/// Puts `source` at `target` the way cargo does: complete, in one rename.
fn replace(source: &Path, target: &Path) {
    let staging = target.with_extension("staging");
    std::fs::copy(source, &staging).unwrap();
    std::fs::rename(&staging, target).unwrap();
}

/// Writes `source` over `target` in several pieces with pauses, the way a linker or cargo
/// writes a library, then returns when the last byte is written.
fn write_in_pieces(source: &Path, target: &Path) {
    use std::io::Write;
    let bytes = std::fs::read(source).unwrap();
    let mut file = std::fs::File::create(target).unwrap();
    for chunk in bytes.chunks(bytes.len() / 3 + 1) {
        file.write_all(chunk).unwrap();
        file.flush().unwrap();
        std::thread::sleep(Duration::from_millis(5));
    }
    file.sync_all().unwrap();
}

/// A host running build 1 from a file in a temp dir, with hot reload on.
fn running_v1(config: HostConfig) -> (HeadlessHost, tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir
        .path()
        .join(onyx_runtime::plugins::plugin_search::library_file_name(
            NAME,
        ));
    std::fs::copy(build(1), &path).unwrap();
    let mut host = HeadlessHost::with_config(config);
    assert_eq!(host.load_plugin_file(&path).unwrap(), NAME);
    host.host_mut().set_hot_reload(true).unwrap();
    host.step(5);
    assert_eq!(
        progress(&host),
        Progress {
            version: 1,
            total: 5,
            reloads_seen: 0
        }
    );
    (host, dir, path)
}

/// Steps frames (in real time) until `done` or a timeout.
fn step_until(
    host: &mut HeadlessHost,
    timeout: Duration,
    mut done: impl FnMut(&HeadlessHost) -> bool,
) -> bool {
    let start = Instant::now();
    while start.elapsed() < timeout {
        host.step(1);
        if done(host) {
            return true;
        }
        std::thread::sleep(Duration::from_millis(2));
    }
    false
}

fn entity_count(host: &HeadlessHost) -> usize {
    host.world().iter().count()
}

#[test]
fn a_rebuilt_file_is_swapped_in_with_state_and_entities_kept() {
    let (mut host, _dir, path) = running_v1(HostConfig::default());
    for i in 0..20 {
        host.host_mut()
            .world_mut()
            .spawn((onyx_plugin_api::Name::new(format!("bystander {i}")),));
    }
    let before = entity_count(&host);
    write_in_pieces(&build(2), &path);
    let swapped = step_until(&mut host, Duration::from_secs(5), |h| {
        progress(h).version == 2
    });
    assert!(swapped, "build 2 never took over: {:?}", progress(&host));
    let p = progress(&host);
    assert_eq!(p.reloads_seen, 1, "the new build was told it is a reload");
    // 5 updates of v1 (+1 each), more v1 frames while waiting, then v2 (+2 each): the total
    // only grows, and never restarted from zero.
    assert!(p.total >= 5 + 2, "state was lost: {p:?}");
    assert_eq!(entity_count(&host), before, "a reload touched the world");
    assert_eq!(host.host().plugin(NAME).unwrap().reloads(), 1);
}

#[test]
fn fifty_consecutive_swaps_lose_nothing() {
    let (mut host, dir, path) = running_v1(HostConfig::default());
    let staging = dir.path().join("staging.so");
    let mut last_total = progress(&host).total;
    let entities = entity_count(&host);
    for swap in 1..=50u32 {
        let version = if swap % 2 == 1 { 2 } else { 1 };
        std::fs::copy(build(version), &staging).unwrap();
        std::fs::rename(&staging, &path).unwrap();
        host.host_mut()
            .reload_plugin(NAME)
            .unwrap_or_else(|e| panic!("swap {swap}: {e}"));
        host.step(2);
        let p = progress(&host);
        assert_eq!(p.version, version, "swap {swap}");
        assert_eq!(
            p.total,
            last_total + 2 * u64::from(version),
            "swap {swap}: state lost"
        );
        assert_eq!(p.reloads_seen, swap);
        // The state counts every reload; a static starts over in each new build.
        let statics: ImageStatics = component(&host, "reloadable", "fixture_reload.progress");
        assert_eq!(
            statics.attaches_in_image, 1,
            "swap {swap}: statics carried over"
        );
        assert_eq!(
            entity_count(&host),
            entities,
            "swap {swap}: entities changed"
        );
        last_total = p.total;
    }
    assert_eq!(host.plugin_status(NAME), Some(&PluginStatus::Running));
}

#[test]
fn touching_the_file_without_changing_it_reloads_nothing() {
    let (mut host, _dir, path) = running_v1(HostConfig::default());
    write_in_pieces(&build(1), &path);
    host.step(1);
    std::thread::sleep(Duration::from_millis(100));
    host.step(3);
    assert_eq!(host.host().plugin(NAME).unwrap().reloads(), 0);
}

#[test]
fn a_broken_build_keeps_the_old_version_running() {
    let journal = journal();
    let mut config = HostConfig::default();
    config.plugin_settings.clear();
    let (mut host, _dir, path) = running_v1(config);
    host.add_plugin("witness", Recorder::new("w", &journal))
        .unwrap();
    // A truncated library, as if the linker had been interrupted.
    let bytes = std::fs::read(build(2)).unwrap();
    std::fs::write(&path, &bytes[..bytes.len() / 2]).unwrap();
    let reported = step_until(&mut host, Duration::from_secs(5), |_| {
        entries(&journal)
            .iter()
            .any(|e| e.contains("PluginReloadFailed"))
    });
    let failures: Vec<String> = entries(&journal)
        .into_iter()
        .filter(|e| e.contains("Reload"))
        .collect();
    assert!(reported, "no PluginReloadFailed event: {failures:?}");
    assert!(failures[0].contains("is incomplete"), "{failures:?}");
    let before = progress(&host).total;
    host.step(3);
    let p = progress(&host);
    assert_eq!(
        (p.version, p.total),
        (1, before + 3),
        "the old build stopped"
    );
    // A direct reload of a text file says why.
    std::fs::write(&path, b"not a library").unwrap();
    let error = host.host_mut().reload_plugin(NAME).unwrap_err();
    assert!(matches!(error, ReloadError::Load { .. }), "{error:?}");
    assert!(error.to_string().contains("could not be loaded"), "{error}");
    assert_eq!(host.plugin_status(NAME), Some(&PluginStatus::Running));
}

#[test]
fn a_build_that_panics_on_attach_keeps_the_old_version_running() {
    let config = HostConfig::default().setting(NAME, "panic_on_reload", "1");
    let (mut host, dir, path) = running_v1(config);
    let staging = dir.path().join("staging.so");
    std::fs::copy(build(2), &staging).unwrap();
    std::fs::rename(&staging, &path).unwrap();
    let error = host.host_mut().reload_plugin(NAME).unwrap_err();
    let ReloadError::Step {
        stage,
        which,
        message,
        ..
    } = &error
    else {
        panic!("{error:?}")
    };
    assert_eq!((*stage, *which), ("on_attach", "new"));
    assert!(message.contains("v2 refuses to be reloaded"), "{message}");
    host.step(3);
    let p = progress(&host);
    assert_eq!(
        (p.version, p.total),
        (1, 8),
        "the old build was not re-attached: {p:?}"
    );
    assert_eq!(host.plugin_status(NAME), Some(&PluginStatus::Running));
}

#[test]
fn a_faulted_plugin_is_revived_by_a_reload() {
    let config = HostConfig::default().setting(NAME, "panic_after", "7");
    let (mut host, dir, path) = running_v1(config);
    host.step(5);
    assert!(matches!(
        host.plugin_status(NAME),
        Some(PluginStatus::Faulted {
            stage: Stage::Update,
            ..
        })
    ));
    let staging = dir.path().join("staging.so");
    std::fs::copy(build(2), &staging).unwrap();
    std::fs::rename(&staging, &path).unwrap();
    host.host_mut().reload_plugin(NAME).unwrap();
    host.step(2);
    assert_eq!(host.plugin_status(NAME), Some(&PluginStatus::Running));
    let p = progress(&host);
    assert_eq!(p.version, 2);
    assert_eq!(
        p.total, 4,
        "a faulted plugin's state is not carried over: {p:?}"
    );
}

/// A plugin revived by a good rebuild after a panic sat idle: its fresh state never got
/// `on_init` (which spawns and sets up), and nothing said it had started over.
#[test]
fn a_revived_plugin_gets_on_init_again_and_the_host_says_it_starts_empty() {
    let config = HostConfig::default().setting(NAME, "panic_after", "7");
    let (mut host, dir, path) = running_v1(config);
    host.step(5);
    assert!(host
        .plugin_status(NAME)
        .is_some_and(PluginStatus::is_faulted));
    let staging = dir.path().join("staging.so");
    std::fs::copy(build(2), &staging).unwrap();
    std::fs::rename(&staging, &path).unwrap();
    let seq = onyx_runtime::console::console_log().last_seq();
    host.host_mut().reload_plugin(NAME).unwrap();
    host.step(2);
    let (e, _) = host
        .find::<onyx_plugin_api::Name>("reloadable")
        .expect("the plugin's entity");
    let blobs = host
        .get::<onyx_runtime::world::PluginComponents>(e)
        .unwrap();
    let published: serde_json::Value =
        serde_json::from_slice(&blobs.0["fixture_reload.progress"].bytes).unwrap();
    assert_eq!(
        published["inits"], 1,
        "the revived build ran on_init once: {published}"
    );
    let said = onyx_runtime::console::console_log()
        .since(seq)
        .into_iter()
        .any(|line| line.message.contains("revived") && line.message.contains("empty state"));
    assert!(
        said,
        "the host logs that the plugin was revived with empty state"
    );
}

#[test]
fn an_in_process_plugin_cannot_be_reloaded() {
    let mut host = HeadlessHost::new();
    host.add_plugin("inproc", Recorder::new("r", &journal()))
        .unwrap();
    assert!(matches!(
        host.host_mut().reload_plugin("inproc"),
        Err(ReloadError::NotFromFile { .. })
    ));
    assert!(matches!(
        host.host_mut().reload_plugin("absent"),
        Err(ReloadError::NotLoaded { .. })
    ));
}

/// Asks for plugin changes through `Ctx`, as the editor's Plugins menu will.
struct Manager {
    frame: u32,
    path: String,
}

impl Plugin for Manager {
    fn on_update(&mut self, ctx: &mut Ctx, _dt: f32) -> Flow {
        self.frame += 1;
        match self.frame {
            1 => ctx.load_plugin(&self.path),
            3 => ctx.reload_plugin(NAME),
            5 => ctx.reload_all_plugins(),
            7 => ctx.unload_plugin(NAME),
            _ => {}
        }
        Flow::Continue
    }
}

#[test]
fn plugins_can_load_reload_and_unload_plugins_through_ctx() {
    let journal = journal();
    let mut host = HeadlessHost::new();
    host.add_plugin("witness", Recorder::new("w", &journal))
        .unwrap();
    let path = build(1).display().to_string();
    host.add_plugin("manager", Manager { frame: 0, path })
        .unwrap();
    host.step(2);
    assert_eq!(host.plugin_status(NAME), Some(&PluginStatus::Running));
    host.step(4);
    // The explicit reload swaps; reload_all leaves the unchanged file alone.
    assert_eq!(host.host().plugin(NAME).unwrap().reloads(), 1);
    host.step(2);
    assert!(host.plugin_status(NAME).is_none());
    let log = entries(&journal);
    for expected in [
        "PluginLoaded { plugin: \"fixture_reload\"",
        "PluginReloaded",
        "PluginUnloaded",
    ] {
        assert!(
            log.iter().any(|e| e.contains(expected)),
            "no {expected}: {log:?}"
        );
    }
}

#[test]
fn a_peers_traffic_flows_through_every_swap_and_no_event_is_lost() {
    let (mut host, _dir, path) = running_v1(HostConfig::default());
    host.load_plugin_file(&plugin_library("fixture-peer"))
        .unwrap();
    host.step(3);
    for swap in 1..=10u32 {
        let version = if swap % 2 == 1 { 2 } else { 1 };
        replace(&build(version), &path);
        if swap % 2 == 0 {
            host.host_mut().reload_plugin(NAME).unwrap();
        } else {
            // Through the watcher, at the start of a frame.
            let swapped = step_until(&mut host, Duration::from_secs(5), |h| {
                progress(h).version == version
            });
            assert!(swapped, "swap {swap} never happened");
        }
        host.step(2);
    }
    let peer: PeerProgress = component(&host, "peer", "fixture_peer.progress");
    let seen: PingCount = component(&host, "reloadable", "fixture_reload.progress");
    // A ping sent in frame n is answered in n + 1 and the answer read in n + 2: all but the
    // last two pings are answered, each once, in order, whichever build answered.
    assert_eq!(peer.gaps, 0, "pongs lost or repeated: {peer:?}");
    assert_eq!(peer.pongs, peer.last_pong, "{peer:?}");
    assert_eq!(peer.last_pong, peer.sent - 2, "{peer:?}");
    assert_eq!(
        seen,
        PingCount {
            pings: peer.sent - 1,
            ping_gaps: 0
        },
        "pings lost across swaps ({peer:?})"
    );
    assert_eq!(peer.versions, [1, 2, 1, 2, 1, 2, 1, 2, 1, 2, 1], "{peer:?}");
    assert_eq!(host.host().plugin(NAME).unwrap().reloads(), 10);
}

#[test]
fn reload_all_swaps_every_changed_library_and_leaves_the_unchanged_ones() {
    let (mut host, dir, path) = running_v1(HostConfig::default());
    let schema = dir
        .path()
        .join(onyx_runtime::plugins::plugin_search::library_file_name(
            "fixture_schema",
        ));
    std::fs::copy(plugin_library("fixture-schema-v1"), &schema).unwrap();
    host.load_plugin_file(&schema).unwrap();
    host.load_plugin_file(&plugin_library("fixture-peer"))
        .unwrap();
    host.step(2);
    replace(&build(2), &path);
    replace(&plugin_library("fixture-schema-added"), &schema);
    let errors = host.host_mut().reload_all();
    assert!(errors.is_empty(), "{errors:?}");
    let reloads = |host: &HeadlessHost, name: &str| host.host().plugin(name).unwrap().reloads();
    assert_eq!(reloads(&host, NAME), 1);
    assert_eq!(reloads(&host, "fixture_schema"), 1);
    assert_eq!(
        reloads(&host, "fixture_peer"),
        0,
        "an unchanged library was swapped"
    );
    host.step(1);
    assert_eq!(progress(&host).version, 2);
    // Nothing changed since: a second reload_all swaps nothing.
    assert!(host.host_mut().reload_all().is_empty());
    assert_eq!(reloads(&host, NAME), 1);
}

#[test]
fn a_released_build_round_swaps_all_its_libraries_in_one_frame() {
    let (mut host, dir, path) = running_v1(HostConfig::default());
    let schema = dir
        .path()
        .join(onyx_runtime::plugins::plugin_search::library_file_name(
            "fixture_schema",
        ));
    std::fs::copy(plugin_library("fixture-schema-v1"), &schema).unwrap();
    host.load_plugin_file(&schema).unwrap();
    host.step(2);
    let schema_build = |host: &HeadlessHost| -> String {
        let published: serde_json::Value = component(host, "schema", "fixture_schema.published");
        published["build"].as_str().unwrap_or_default().to_owned()
    };
    // `onyx dev` holds the reloads while its builds run, as if the two were rebuilt in turn.
    let gate = host.host().reload_gate();
    gate.hold();
    replace(&build(2), &path);
    std::thread::sleep(Duration::from_millis(50));
    host.step(3);
    replace(&plugin_library("fixture-schema-added"), &schema);
    std::thread::sleep(Duration::from_millis(50));
    host.step(3);
    assert_eq!(
        (progress(&host).version, schema_build(&host).as_str()),
        (1, "v1"),
        "a library was swapped while the round was held"
    );
    gate.release([path.clone(), schema.clone()]);
    host.step(1);
    assert_eq!(
        (progress(&host).version, schema_build(&host).as_str()),
        (2, "added"),
        "the round's libraries did not swap in the same frame"
    );
    host.step(5);
    assert_eq!(host.host().plugin(NAME).unwrap().reloads(), 1);
    assert_eq!(host.host().plugin("fixture_schema").unwrap().reloads(), 1);
}
