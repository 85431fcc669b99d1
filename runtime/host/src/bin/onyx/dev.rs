//! `onyx dev --plugin-crate DIR...`: build plugin crates, run them, rebuild them in the
//! background when their sources change; the host hot-reloads each rebuilt library.
//!
//! Processes: `onyx dev` builds and watches; the host runs in a child process
//! (`onyx dev-host`, with the same arguments and the built libraries), so a native crash in a
//! plugin ends only the child: `onyx dev` reports it and starts a new host after the next
//! good build.
//!
//! Threads of `onyx dev`: a notify watcher feeds one coordinator thread, which debounces
//! changes per crate and wakes that crate's builder thread. Each builder runs one
//! `cargo build` at a time and, if changes came in meanwhile, another after it. The main
//! thread waits for the host process. In the host, the library watcher notices the rewritten
//! cdylib, waits until it is complete, and reloads the plugin at the start of a frame, keeping
//! the old build when the new one cannot load; frames never wait for a build.

use std::collections::HashMap;
use std::ffi::OsString;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::mpsc::{channel, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use anyhow::{anyhow, Context as _};
use notify::{RecursiveMode, Watcher};
use onyx_runtime::window::run_windowed;
use onyx_runtime::Host;

use crate::cli::{DevArgs, DevHostArgs};
use crate::Failure;

/// How long sources must be left alone before a rebuild starts (editors write in bursts).
pub const DEBOUNCE: Duration = Duration::from_millis(200);

/// Frames per second of a headless dev run.
const HEADLESS_FPS: f64 = 60.0;

/// A plugin crate under development.
#[derive(Clone, Debug)]
struct PluginCrate {
    /// Its directory, absolute.
    dir: PathBuf,
    /// `dir/Cargo.toml`.
    manifest: PathBuf,
    /// What to call it in messages: the directory's name.
    label: String,
}

/// A builder's running `cargo build`, shared with the main thread so it can be stopped.
#[derive(Debug, Default)]
struct BuildSlot {
    /// The build in progress.
    child: Option<Child>,
    /// Set at exit: start no more builds.
    stopped: bool,
}

fn lock(slot: &Mutex<BuildSlot>) -> std::sync::MutexGuard<'_, BuildSlot> {
    slot.lock().unwrap_or_else(|e| e.into_inner())
}

/// What one `cargo build` produced.
#[derive(Debug)]
struct Built {
    /// The crate's cdylib, if the build produced (or found up to date) one.
    library: Option<PathBuf>,
    /// Whether the library was already up to date.
    fresh: bool,
}

/// The `cargo` to run: the one that ran us (`$CARGO`), else `cargo` from the PATH.
fn cargo() -> OsString {
    std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into())
}

fn same_file(a: &Path, b: &Path) -> bool {
    a == b || matches!((a.canonicalize(), b.canonicalize()), (Ok(a), Ok(b)) if a == b)
}

impl PluginCrate {
    fn new(dir: &Path) -> anyhow::Result<Self> {
        let dir = std::path::absolute(dir).unwrap_or_else(|_| dir.to_path_buf());
        let dir = dir.canonicalize().unwrap_or(dir);
        let manifest = dir.join("Cargo.toml");
        if !manifest.is_file() {
            return Err(anyhow!(
                "`{}` is not a crate: it has no Cargo.toml",
                dir.display()
            ));
        }
        let label = dir
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_else(|| dir.display().to_string());
        Ok(Self {
            dir,
            manifest,
            label,
        })
    }

    /// Whether a change to `path` calls for a rebuild.
    fn is_source(&self, path: &Path) -> bool {
        let Ok(rel) = path.strip_prefix(&self.dir) else {
            return false;
        };
        let hidden_or_backup = path.file_name().is_some_and(|n| {
            let n = n.to_string_lossy();
            n.starts_with('.') || n.ends_with('~') || n.ends_with(".swp") || n.ends_with(".swx")
        });
        if hidden_or_backup {
            return false;
        }
        rel.starts_with("src") || rel == Path::new("Cargo.toml") || rel == Path::new("build.rs")
    }

    /// Runs `cargo build` for this crate: the compiler's messages go to our stderr, the JSON
    /// messages on its stdout tell where the cdylib is. `slot` holds the child while it
    /// runs, so it can be stopped at exit.
    fn build(&self, slot: &Mutex<BuildSlot>) -> anyhow::Result<Built> {
        let mut running = lock(slot);
        if running.stopped {
            return Err(anyhow!("stopped"));
        }
        let mut child = Command::new(cargo())
            .arg("build")
            .arg("--manifest-path")
            .arg(&self.manifest)
            .arg("--message-format=json-render-diagnostics")
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .with_context(|| format!("cannot run `{}`", cargo().to_string_lossy()))?;
        let stdout = child.stdout.take().expect("stdout is piped");
        running.child = Some(child);
        drop(running);
        let mut built = Built {
            library: None,
            fresh: false,
        };
        for line in BufReader::new(stdout).lines() {
            let Ok(line) = line else { break };
            let Ok(message) = serde_json::from_str::<serde_json::Value>(&line) else {
                continue; // a build script's output, passed through as text
            };
            if let Some((library, fresh)) = self.cdylib_in(&message) {
                built = Built {
                    library: Some(library),
                    fresh,
                };
            }
        }
        let child = lock(slot).child.take();
        let status = match child {
            Some(mut child) => child.wait().context("cannot wait for cargo")?,
            None => return Err(anyhow!("stopped")),
        };
        if !status.success() {
            return Err(anyhow!(
                "`cargo build` failed for `{}` ({status}); the compiler's errors are above",
                self.dir.display()
            ));
        }
        Ok(built)
    }

    /// The cdylib file of this crate in a `compiler-artifact` message, with its `fresh` flag.
    fn cdylib_in(&self, message: &serde_json::Value) -> Option<(PathBuf, bool)> {
        if message["reason"] != "compiler-artifact" {
            return None;
        }
        let manifest = Path::new(message["manifest_path"].as_str()?);
        let is_cdylib = message["target"]["kind"]
            .as_array()?
            .iter()
            .any(|k| k == "cdylib");
        if !is_cdylib || !same_file(manifest, &self.manifest) {
            return None;
        }
        let library = message["filenames"]
            .as_array()?
            .iter()
            .filter_map(|f| f.as_str())
            .find(|f| f.ends_with(std::env::consts::DLL_SUFFIX))?;
        Some((PathBuf::from(library), message["fresh"] == true))
    }
}

/// A crate's builder: a thread that runs one build at a time when told to.
struct Builder {
    wake: Sender<()>,
    slot: Arc<Mutex<BuildSlot>>,
}

impl Builder {
    /// Starts the builder; it sends on `built` after each good build.
    fn spawn(krate: PluginCrate, library: PathBuf, built: Sender<()>) -> Self {
        let (wake, woken) = channel::<()>();
        let slot = Arc::new(Mutex::new(BuildSlot::default()));
        let shared = slot.clone();
        std::thread::Builder::new()
            .name(format!("build {}", krate.label))
            .spawn(move || build_loop(&krate, &library, &woken, &shared, &built))
            .expect("can start a builder thread");
        Self { wake, slot }
    }

    /// Kills the build in progress, if any, and starts no more.
    fn stop(&self) {
        let mut slot = lock(&self.slot);
        slot.stopped = true;
        if let Some(child) = slot.child.as_mut() {
            let _ = child.kill();
        }
    }
}

fn build_loop(
    krate: &PluginCrate,
    library: &Path,
    woken: &Receiver<()>,
    slot: &Mutex<BuildSlot>,
    built_ok: &Sender<()>,
) {
    while woken.recv().is_ok() {
        while woken.try_recv().is_ok() {} // changes queued up before now: one build covers them
        tracing::info!(plugin_crate = %krate.label, "sources changed; rebuilding");
        let started = Instant::now();
        let result = krate.build(slot);
        if lock(slot).stopped {
            return; // `onyx dev` is exiting
        }
        match result {
            Ok(Built {
                library: Some(built),
                fresh,
            }) => {
                let seconds = format!("{:.1}s", started.elapsed().as_secs_f64());
                if fresh {
                    tracing::info!(plugin_crate = %krate.label, "up to date; nothing to reload");
                } else {
                    tracing::info!(
                        plugin_crate = %krate.label,
                        library = %built.display(),
                        "rebuilt in {seconds}; the host reloads it if the library changed"
                    );
                }
                if !same_file(&built, library) {
                    tracing::warn!(
                        plugin_crate = %krate.label,
                        "the crate now builds `{}`, not `{}` (loaded at start): restart `onyx dev`",
                        built.display(),
                        library.display()
                    );
                }
                let _ = built_ok.send(());
            }
            Ok(Built { library: None, .. }) => tracing::error!(
                plugin_crate = %krate.label,
                "the build produced no cdylib; the previous build keeps running"
            ),
            Err(error) => tracing::error!(
                plugin_crate = %krate.label,
                "build failed: {error:#}; the previous build keeps running"
            ),
        }
    }
}

/// Debounces file events per crate and wakes the builders. Returns when the watcher is gone.
fn coordinate(
    events: &Receiver<notify::Result<notify::Event>>,
    crates: &[(PluginCrate, Sender<()>)],
) {
    let mut dirty: HashMap<usize, Instant> = HashMap::new();
    loop {
        let now = Instant::now();
        let timeout = dirty
            .values()
            .map(|since| (*since + DEBOUNCE).saturating_duration_since(now))
            .min()
            .unwrap_or(Duration::from_secs(3600));
        match events.recv_timeout(timeout) {
            Ok(Ok(event)) => {
                if !matches!(event.kind, notify::EventKind::Access(_)) {
                    for path in &event.paths {
                        for (index, (krate, _)) in crates.iter().enumerate() {
                            if krate.is_source(path) {
                                tracing::debug!(path = %path.display(), "source changed");
                                dirty.insert(index, Instant::now());
                            }
                        }
                    }
                }
            }
            Ok(Err(error)) => tracing::warn!("file watching: {error}"),
            Err(RecvTimeoutError::Timeout) => {}
            Err(RecvTimeoutError::Disconnected) => return,
        }
        let now = Instant::now();
        dirty.retain(|index, since| {
            if now.duration_since(*since) < DEBOUNCE {
                return true;
            }
            let _ = crates[*index].1.send(());
            false
        });
    }
}

/// Watches each crate's `src/` (recursively) and its directory (for `Cargo.toml` and
/// `build.rs`, which editors may replace rather than rewrite).
fn watch(
    crates: &[PluginCrate],
) -> anyhow::Result<(
    notify::RecommendedWatcher,
    Receiver<notify::Result<notify::Event>>,
)> {
    let (tx, rx) = channel();
    let mut watcher = notify::recommended_watcher(move |event| {
        let _ = tx.send(event);
    })
    .context("cannot start watching files")?;
    for krate in crates {
        let src = krate.dir.join("src");
        if src.is_dir() {
            watcher
                .watch(&src, RecursiveMode::Recursive)
                .with_context(|| format!("cannot watch `{}`", src.display()))?;
        }
        watcher
            .watch(&krate.dir, RecursiveMode::NonRecursive)
            .with_context(|| format!("cannot watch `{}`", krate.dir.display()))?;
    }
    Ok((watcher, rx))
}

/// Runs `onyx dev`.
pub fn dev(args: DevArgs) -> Result<(), Failure> {
    // 1. First builds: any failure stops here.
    let mut crates = Vec::new();
    let mut libraries = Vec::new();
    for dir in &args.plugin_crates {
        let krate = PluginCrate::new(dir).map_err(Failure::Start)?;
        tracing::info!(plugin_crate = %krate.label, dir = %krate.dir.display(), "building");
        let built = krate
            .build(&Mutex::new(BuildSlot::default()))
            .map_err(Failure::Start)?;
        let library = built.library.ok_or_else(|| {
            Failure::Start(anyhow!(
                "`{}` builds no cdylib: a plugin crate needs [lib] crate-type = [\"cdylib\", ...]",
                krate.manifest.display()
            ))
        })?;
        libraries.push(library);
        crates.push(krate);
    }

    // 2. Watch the sources; a builder per crate.
    let (watcher, events) = watch(&crates).map_err(Failure::Start)?;
    let (built_ok, good_builds) = channel();
    let mut builders = Vec::new();
    let mut wakers = Vec::new();
    for (krate, library) in crates.into_iter().zip(libraries.iter().cloned()) {
        let builder = Builder::spawn(krate.clone(), library, built_ok.clone());
        wakers.push((krate, builder.wake.clone()));
        builders.push(builder);
    }
    std::thread::Builder::new()
        .name("watch sources".into())
        .spawn(move || coordinate(&events, &wakers))
        .expect("can start the watcher thread");
    tracing::info!("watching the plugin sources; save a change to rebuild and reload");

    // 3. The host, in a process of its own, started again after a crash and a good build.
    let result = supervise(&libraries, &good_builds);

    // 4. Stop watching, stop builds in progress.
    drop(watcher);
    for builder in &builders {
        builder.stop();
    }
    result
}

/// Runs host processes until one ends on its own terms: a clean end (`Ok`), faults at the end
/// (exit 1, already reported), or a first start that failed (exit 2, already reported). After
/// a crash — or a failed start of a new build — it waits for the next good build.
fn supervise(libraries: &[PathBuf], good_builds: &Receiver<()>) -> Result<(), Failure> {
    let mut first = true;
    loop {
        let status = run_host_process(libraries).map_err(Failure::Start)?;
        match status.code() {
            Some(0) => return Ok(()),
            Some(1) => return Err(Failure::Reported(1)),
            Some(2) if first => return Err(Failure::Reported(2)),
            _ => {}
        }
        first = false;
        // Builds that finished before the host stopped are the ones it ran (or crashed on).
        while good_builds.try_recv().is_ok() {}
        tracing::warn!(
            "the host stopped ({}); still watching the plugin sources: save a fix and the next \
             good build starts it again",
            describe_status(status)
        );
        if good_builds.recv().is_err() {
            return Err(Failure::Reported(3));
        }
        tracing::info!("a good build: starting the host again");
    }
}

/// Runs `onyx dev-host` with this process's `dev` arguments and `libraries`; its output is
/// ours.
fn run_host_process(libraries: &[PathBuf]) -> anyhow::Result<ExitStatus> {
    let exe =
        std::env::current_exe().context("cannot find the onyx executable to start the host")?;
    let mut args: Vec<OsString> = std::env::args_os().collect();
    let dev_at = 1 + args
        .iter()
        .skip(1)
        .position(|a| a == "dev")
        .context("`onyx dev` was not started as `onyx dev ...`")?;
    let dev_args = args.split_off(dev_at + 1);
    let mut command = Command::new(exe);
    command.arg("dev-host");
    for library in libraries {
        command.arg("--library").arg(library);
    }
    command.args(dev_args);
    let mut child = command.spawn().context("cannot start the host process")?;
    child.wait().context("cannot wait for the host process")
}

fn describe_status(status: ExitStatus) -> String {
    if let Some(code) = status.code() {
        return format!("exit status {code}");
    }
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt as _;
        if let Some(signal) = status.signal() {
            return format!("killed by signal {signal}");
        }
    }
    status.to_string()
}

/// Runs `onyx dev-host`: the host `onyx dev` watches, with hot reload on.
pub fn dev_host(args: DevHostArgs) -> Result<(), Failure> {
    let mut host = crate::start_host(&args.dev.host, &args.libraries)?;
    host.set_hot_reload(true)
        .context("cannot watch the plugin libraries")
        .map_err(Failure::Start)?;
    let frames = if args.dev.host.headless {
        run_headless(&mut host, args.dev.host.frames)
    } else {
        let options = crate::window_options(&args.dev.host, "Onyx dev");
        run_windowed(&mut host, options)
            .map(|summary| summary.frames)
            .map_err(|e| Failure::Start(anyhow::Error::new(e)))?
    };
    host.shutdown();
    tracing::info!(frames, ticks = host.time().ticks, "dev run finished");
    crate::check_faults(&host)
}

/// Runs frames in real time (about [`HEADLESS_FPS`] a second) until `frames` or a quit.
fn run_headless(host: &mut Host, frames: Option<u64>) -> u64 {
    let interval = Duration::from_secs_f64(1.0 / HEADLESS_FPS);
    let mut last = Instant::now() - interval;
    let mut next = Instant::now();
    let mut count = 0u64;
    while frames.is_none_or(|n| count < n) {
        let now = Instant::now();
        let dt = now.duration_since(last).as_secs_f64();
        last = now;
        count += 1;
        if host.frame(dt).quit {
            break;
        }
        next += interval;
        let now = Instant::now();
        if next > now {
            std::thread::sleep(next - now);
        } else {
            next = now; // behind (a reload, a slow frame): do not try to catch up
        }
    }
    count
}

#[cfg(test)]
mod tests {
    use super::*;

    fn krate(dir: &Path) -> PluginCrate {
        PluginCrate {
            dir: dir.to_path_buf(),
            manifest: dir.join("Cargo.toml"),
            label: "demo".into(),
        }
    }

    #[test]
    fn only_sources_and_manifests_trigger_builds() {
        let k = krate(Path::new("/w/demo"));
        for yes in [
            "/w/demo/src/lib.rs",
            "/w/demo/src/a/b.rs",
            "/w/demo/Cargo.toml",
            "/w/demo/build.rs",
        ] {
            assert!(k.is_source(Path::new(yes)), "{yes}");
        }
        for no in [
            "/w/demo/target/debug/libdemo.so",
            "/w/demo/Cargo.lock",
            "/w/demo/src/.lib.rs.swp",
            "/w/demo/src/lib.rs~",
            "/w/other/src/lib.rs",
        ] {
            assert!(!k.is_source(Path::new(no)), "{no}");
        }
    }

    #[test]
    fn the_cdylib_is_found_in_cargo_messages() {
        let k = krate(Path::new("/w/demo"));
        let lib = format!("/t/debug/libdemo{}", std::env::consts::DLL_SUFFIX);
        let message = serde_json::json!({
            "reason": "compiler-artifact",
            "manifest_path": "/w/demo/Cargo.toml",
            "target": {"kind": ["cdylib", "rlib"]},
            "filenames": ["/t/debug/libdemo.rlib", lib],
            "fresh": true,
        });
        assert_eq!(k.cdylib_in(&message), Some((PathBuf::from(&lib), true)));
        let mut other = message.clone();
        other["manifest_path"] = "/w/dep/Cargo.toml".into();
        assert_eq!(k.cdylib_in(&other), None);
        let mut rlib_only = message.clone();
        rlib_only["target"]["kind"] = serde_json::json!(["lib"]);
        assert_eq!(k.cdylib_in(&rlib_only), None);
    }
}
