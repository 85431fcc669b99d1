//! `onyx dev --plugin-crate DIR...`: build plugin crates, run them, rebuild them in the
//! background when their sources change; the host hot-reloads each rebuilt library.
//!
//! Processes: `onyx dev` builds and watches; the host runs in a child process
//! (`onyx dev-host`, with the same arguments and the built libraries), so a native crash in a
//! plugin ends only the child: `onyx dev` reports it and starts a new host after the next
//! good build.
//!
//! What is watched: for each plugin crate, `cargo metadata` names every local crate it is
//! built from — itself, its path dependencies and workspace siblings, transitively (normal and
//! build dependencies) — and each one's source folders, manifest and build script are watched
//! (`crate_graph.rs`). An edit in a shared crate rebuilds every plugin crate that depends on
//! it; a changed manifest asks cargo again after the build.
//!
//! Threads of `onyx dev`: a notify watcher feeds one coordinator thread, which debounces
//! changes and starts a *round*: it tells the host to hold its reloads, wakes the builder
//! thread of every crate the changes touch (each runs one `cargo build` at a time) and, when
//! all of them have finished, tells the host which libraries the round built. The host swaps
//! every one of them that changed in one frame — plugins that share a crate never run one old
//! and one new — keeping the old build of any that cannot load. The main thread waits for
//! the host process; frames never wait for a build. The host hears the coordinator on its
//! standard input, one line per message (`hold`, `swap` and a JSON list of library paths).

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
use onyx_runtime::plugins::ReloadGate;
use onyx_runtime::window::run_windowed;
use onyx_runtime::Host;

use crate::cli::{DevArgs, DevHostArgs};
use crate::crate_graph::CrateSources;
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
    /// Every file whose change rebuilds it (its local dependencies' too).
    sources: CrateSources,
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
        let sources = own_sources(&dir, &label);
        Ok(Self {
            dir,
            manifest,
            label,
            sources,
        })
    }

    /// Asks cargo which local crates this one is built from (after a build, so the lock
    /// file is there). On failure the crate's own folder stays watched.
    fn find_sources(&mut self) {
        match CrateSources::of(&cargo(), &self.manifest) {
            Ok(sources) => {
                if sources.packages.len() > 1 {
                    tracing::info!(
                        plugin_crate = %self.label,
                        "also watching the local crates it is built from: {}",
                        sources.packages[1..].join(", ")
                    );
                }
                self.sources = sources;
            }
            Err(error) => tracing::warn!(
                plugin_crate = %self.label,
                "cannot list the crates it depends on ({error:#}); watching only its own sources"
            ),
        }
    }

    /// Whether a change to `path` calls for a rebuild.
    fn is_source(&self, path: &Path) -> bool {
        self.sources.contains(path)
    }

    /// Whether a change to `path` may change which crates it is built from.
    fn is_manifest(&self, path: &Path) -> bool {
        path.file_name()
            .is_some_and(|n| n == "Cargo.toml" || n == "Cargo.lock")
            && self.sources.files.contains(path)
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

/// What the coordinator hears: file changes, and builders finishing.
enum Message {
    /// A file event from the watcher.
    File(notify::Result<notify::Event>),
    /// Crate `index` finished a build: the library it built, if the build was good.
    Built {
        index: usize,
        library: Option<PathBuf>,
    },
}

/// What is watched of a crate before cargo has said more: its `src/`, manifest and build
/// script.
fn own_sources(dir: &Path, label: &str) -> CrateSources {
    CrateSources {
        packages: vec![label.to_owned()],
        dirs: [dir.join("src")].into(),
        files: [dir.join("Cargo.toml"), dir.join("build.rs")].into(),
    }
}

/// A crate's builder: a thread that runs one build at a time when told to.
struct Builder {
    wake: Sender<()>,
    slot: Arc<Mutex<BuildSlot>>,
}

impl Builder {
    /// Starts the builder; it reports each build's end to the coordinator.
    fn spawn(index: usize, krate: PluginCrate, library: PathBuf, done: Sender<Message>) -> Self {
        let (wake, woken) = channel::<()>();
        let slot = Arc::new(Mutex::new(BuildSlot::default()));
        let shared = slot.clone();
        std::thread::Builder::new()
            .name(format!("build {}", krate.label))
            .spawn(move || build_loop(index, &krate, &library, &woken, &shared, &done))
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
    index: usize,
    krate: &PluginCrate,
    library: &Path,
    woken: &Receiver<()>,
    slot: &Mutex<BuildSlot>,
    done: &Sender<Message>,
) {
    while woken.recv().is_ok() {
        while woken.try_recv().is_ok() {} // changes queued up before now: one build covers them
        tracing::info!(plugin_crate = %krate.label, "sources changed; rebuilding");
        let started = Instant::now();
        let result = krate.build(slot);
        if lock(slot).stopped {
            return; // `onyx dev` is exiting
        }
        let built = match result {
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
                Some(library.to_path_buf())
            }
            Ok(Built { library: None, .. }) => {
                tracing::error!(
                    plugin_crate = %krate.label,
                    "the build produced no cdylib; the previous build keeps running"
                );
                None
            }
            Err(error) => {
                tracing::error!(
                    plugin_crate = %krate.label,
                    "build failed: {error:#}; the previous build keeps running"
                );
                None
            }
        };
        if done
            .send(Message::Built {
                index,
                library: built,
            })
            .is_err()
        {
            return;
        }
    }
}

/// The host process's standard input, while one runs: where rounds are announced.
type HostControl = Arc<Mutex<Option<std::process::ChildStdin>>>;

/// Tells the host one line; a host that is gone (crashed, restarting) misses it, which is
/// fine: a new host loads the libraries as they are.
fn tell_host(control: &HostControl, line: &str) {
    use std::io::Write as _;
    let mut stdin = control.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(pipe) = stdin.as_mut() {
        if writeln!(pipe, "{line}")
            .and_then(|()| pipe.flush())
            .is_err()
        {
            *stdin = None;
        }
    }
}

/// The coordinator's view of the crates: their sources, their builders, the round running.
struct Coordinator {
    crates: Vec<PluginCrate>,
    wakers: Vec<Sender<()>>,
    watcher: notify::RecommendedWatcher,
    watched: Vec<(PathBuf, bool)>,
    control: HostControl,
    good_builds: Sender<()>,
    /// Crates with changes not yet built, and when each last changed.
    dirty: HashMap<usize, Instant>,
    /// Crates whose manifests changed: ask cargo again after their build.
    manifests_changed: Vec<usize>,
    /// The round being built: crates still building, libraries built so far.
    building: Vec<usize>,
    built: Vec<PathBuf>,
}

impl Coordinator {
    /// Debounces file events, runs build rounds and tells the host. Returns when the
    /// watcher is gone.
    fn run(mut self, events: &Receiver<Message>) {
        loop {
            let now = Instant::now();
            let timeout = self
                .dirty
                .values()
                .map(|since| (*since + DEBOUNCE).saturating_duration_since(now))
                .min()
                .unwrap_or(Duration::from_secs(3600));
            match events.recv_timeout(timeout) {
                Ok(Message::File(Ok(event))) => self.file_changed(&event),
                Ok(Message::File(Err(error))) => tracing::warn!("file watching: {error}"),
                Ok(Message::Built { index, library }) => self.build_finished(index, library),
                Err(RecvTimeoutError::Timeout) => {}
                Err(RecvTimeoutError::Disconnected) => return,
            }
            self.start_round();
        }
    }

    fn file_changed(&mut self, event: &notify::Event) {
        if matches!(event.kind, notify::EventKind::Access(_)) {
            return;
        }
        for path in &event.paths {
            for (index, krate) in self.crates.iter().enumerate() {
                if krate.is_source(path) {
                    tracing::debug!(path = %path.display(), plugin_crate = %krate.label, "source changed");
                    self.dirty.insert(index, Instant::now());
                    if krate.is_manifest(path) && !self.manifests_changed.contains(&index) {
                        self.manifests_changed.push(index);
                    }
                }
            }
        }
    }

    /// Starts a round with every crate whose changes have settled, unless one is running
    /// (its crates' new changes wait for the next).
    fn start_round(&mut self) {
        if !self.building.is_empty() {
            return;
        }
        let now = Instant::now();
        let settled: Vec<usize> = self
            .dirty
            .iter()
            .filter(|(_, since)| now.duration_since(**since) >= DEBOUNCE)
            .map(|(index, _)| *index)
            .collect();
        if settled.is_empty() {
            return;
        }
        // Every crate that changed in the same burst goes into this round.
        let round: Vec<usize> = self.dirty.drain().map(|(index, _)| index).collect();
        if round.len() > 1 {
            let labels: Vec<&str> = round
                .iter()
                .map(|i| self.crates[*i].label.as_str())
                .collect();
            tracing::info!(
                "rebuilding {} plugin crates together: {}",
                round.len(),
                labels.join(", ")
            );
        }
        tell_host(&self.control, "hold");
        for index in &round {
            let _ = self.wakers[*index].send(());
        }
        self.building = round;
        self.built.clear();
    }

    fn build_finished(&mut self, index: usize, library: Option<PathBuf>) {
        self.building.retain(|i| *i != index);
        if let Some(library) = library {
            self.built.push(library);
        }
        if let Some(at) = self.manifests_changed.iter().position(|i| *i == index) {
            self.manifests_changed.remove(at);
            self.crates[index].find_sources();
            self.watch_all();
        }
        if !self.building.is_empty() {
            return;
        }
        let built = std::mem::take(&mut self.built);
        let paths: Vec<String> = built.iter().map(|p| p.display().to_string()).collect();
        let list = serde_json::to_string(&paths).unwrap_or_else(|_| "[]".into());
        tell_host(&self.control, &format!("swap {list}"));
        if !built.is_empty() {
            let _ = self.good_builds.send(());
        }
    }

    /// Watches what the crates' sources need and is not watched yet.
    fn watch_all(&mut self) {
        for krate in &self.crates {
            for (dir, recursive) in krate.sources.watch_list() {
                if self
                    .watched
                    .iter()
                    .any(|(d, r)| *d == dir && (*r || !recursive))
                {
                    continue;
                }
                let mode = if recursive {
                    RecursiveMode::Recursive
                } else {
                    RecursiveMode::NonRecursive
                };
                match self.watcher.watch(&dir, mode) {
                    Ok(()) => self.watched.push((dir, recursive)),
                    Err(error) => {
                        tracing::warn!(dir = %dir.display(), "cannot watch: {error}")
                    }
                }
            }
        }
    }
}

/// Runs `onyx dev`.
pub fn dev(args: DevArgs) -> Result<(), Failure> {
    // 1. First builds: any failure stops here.
    let mut crates = Vec::new();
    let mut libraries = Vec::new();
    for dir in &args.plugin_crates {
        let mut krate = PluginCrate::new(dir).map_err(Failure::Start)?;
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
        krate.find_sources();
        libraries.push(library);
        crates.push(krate);
    }

    // 2. Watch the sources (every local crate each plugin is built from); a builder per crate.
    let (messages, events) = channel();
    let file_events = messages.clone();
    let watcher = notify::recommended_watcher(move |event| {
        let _ = file_events.send(Message::File(event));
    })
    .context("cannot start watching files")
    .map_err(Failure::Start)?;
    let (good_builds_tx, good_builds) = channel();
    let control: HostControl = Arc::default();
    let mut builders = Vec::new();
    for (index, (krate, library)) in crates.iter().zip(&libraries).enumerate() {
        builders.push(Builder::spawn(
            index,
            krate.clone(),
            library.clone(),
            messages.clone(),
        ));
    }
    let mut coordinator = Coordinator {
        wakers: builders.iter().map(|b| b.wake.clone()).collect(),
        crates,
        watcher,
        watched: Vec::new(),
        control: control.clone(),
        good_builds: good_builds_tx,
        dirty: HashMap::new(),
        manifests_changed: Vec::new(),
        building: Vec::new(),
        built: Vec::new(),
    };
    coordinator.watch_all();
    if coordinator.watched.is_empty() {
        return Err(Failure::Start(anyhow!(
            "cannot watch any of the plugin sources"
        )));
    }
    drop(messages);
    std::thread::Builder::new()
        .name("watch sources".into())
        .spawn(move || coordinator.run(&events))
        .expect("can start the watcher thread");
    tracing::info!("watching the plugin sources; save a change to rebuild and reload");

    // 3. The host, in a process of its own, started again after a crash and a good build.
    let result = supervise(&libraries, &good_builds, &control);

    // 4. Stop builds in progress (the watcher goes with the coordinator at exit).
    for builder in &builders {
        builder.stop();
    }
    result
}

/// Runs host processes until one ends on its own terms: a clean end (`Ok`), faults at the end
/// (exit 1, already reported), or a first start that failed (exit 2, already reported). After
/// a crash — or a failed start of a new build — it waits for the next good build.
fn supervise(
    libraries: &[PathBuf],
    good_builds: &Receiver<()>,
    control: &HostControl,
) -> Result<(), Failure> {
    let mut first = true;
    loop {
        let status = run_host_process(libraries, control).map_err(Failure::Start)?;
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
/// ours, its input is `control` (the build rounds) while it runs.
fn run_host_process(libraries: &[PathBuf], control: &HostControl) -> anyhow::Result<ExitStatus> {
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
    command.args(dev_args).stdin(Stdio::piped());
    let mut child = command.spawn().context("cannot start the host process")?;
    *control.lock().unwrap_or_else(|e| e.into_inner()) = child.stdin.take();
    let status = child.wait().context("cannot wait for the host process");
    *control.lock().unwrap_or_else(|e| e.into_inner()) = None;
    status
}

/// Reads `onyx dev`'s round messages from standard input and passes them to `gate`; at the
/// end of input (`onyx dev` is gone) nothing stays held.
fn follow_rounds(gate: ReloadGate) {
    for line in std::io::stdin().lines() {
        let Ok(line) = line else { break };
        if line == "hold" {
            gate.hold();
        } else if let Some(list) = line.strip_prefix("swap ") {
            match serde_json::from_str::<Vec<PathBuf>>(list) {
                Ok(libraries) => gate.release(libraries),
                Err(error) => {
                    tracing::warn!("onyx dev sent a swap the host cannot read ({error}): {line}");
                    gate.release([]);
                }
            }
        }
    }
    gate.release([]);
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
    let gate = host.reload_gate();
    std::thread::Builder::new()
        .name("dev rounds".into())
        .spawn(move || follow_rounds(gate))
        .expect("can start the thread that reads onyx dev's messages");
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
            sources: own_sources(dir, "demo"),
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
