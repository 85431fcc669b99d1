//! The plugin developer's loop with the real `onyx` binary: `onyx new-plugin` scaffolds a
//! crate that builds and passes its tests; `onyx dev` runs it, rebuilds it when its source
//! changes and hot-reloads it with its state, and keeps running through a compile error; an
//! edit in a crate two plugins share rebuilds both and swaps them in one frame, keeping
//! their state when serde can map it and refusing the swap when it cannot.
//!
//! The scaffolded crates build into this build's own target directory, as the README tells
//! a plugin author to (`CARGO_TARGET_DIR=<checkout>/target`): they reuse every dependency
//! already compiled there (cargo lets go of the directory's lock once the test binaries are
//! built), so only the four Onyx crates and the scaffolded crate compile. They take turns.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::{Duration, Instant};

use onyx_tests::{onyx_binary, target_dir};

/// The tests that build a scaffolded crate take turns (one cargo at a time in the target
/// directory).
static SCAFFOLD_TARGET: Mutex<()> = Mutex::new(());

fn scaffold_target_lock() -> MutexGuard<'static, ()> {
    SCAFFOLD_TARGET.lock().unwrap_or_else(|e| e.into_inner())
}

/// Where scaffolded crates are built: the target directory of this build (`target/`). Their
/// names start `fixture-`, so `onyx plugins` does not list the libraries they leave there.
fn scaffold_target_dir() -> PathBuf {
    target_dir()
        .parent()
        .expect("target/debug has a parent")
        .to_path_buf()
}

fn onyx(args: &[&str]) -> Output {
    Command::new(onyx_binary())
        .args(args)
        .env("RUST_LOG", "warn")
        .env("NO_COLOR", "1")
        .output()
        .expect("onyx runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

fn tail(text: &str, lines: usize) -> String {
    let all: Vec<&str> = text.lines().collect();
    all[all.len().saturating_sub(lines)..].join("\n")
}

/// `onyx new-plugin NAME --path DIR`, asserted to succeed. Returns the crate's directory.
fn new_plugin(name: &str, parent: &Path) -> PathBuf {
    let out = onyx(&["new-plugin", name, "--path", parent.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "new-plugin {name}: exit {:?}\n{}",
        out.status,
        text(&out.stderr)
    );
    let dir = parent.join(name);
    assert!(
        dir.join("Cargo.toml").is_file(),
        "no Cargo.toml in {}",
        dir.display()
    );
    dir
}

#[test]
fn new_plugin_scaffolds_a_crate_that_builds_and_passes_its_tests() {
    let parent = tempfile::tempdir().unwrap();
    let dir = new_plugin("fixture-scaffold-check", parent.path());

    let manifest = std::fs::read_to_string(dir.join("Cargo.toml")).unwrap();
    for needle in [
        "name = \"fixture-scaffold-check\"",
        "crate-type = [\"cdylib\", \"rlib\"]",
        "[workspace]",
        "onyx-plugin-api = { path = ",
        "onyx-runtime = { path = ",
    ] {
        assert!(
            manifest.contains(needle),
            "Cargo.toml lacks {needle}:\n{manifest}"
        );
    }
    let readme = std::fs::read_to_string(dir.join("README.md")).unwrap();
    for needle in [
        "cargo build",
        "cargo test",
        "onyx dev --plugin-crate .",
        "onyx run --plugin target/debug/",
        "survives a hot reload",
    ] {
        assert!(readme.contains(needle), "README.md lacks {needle}");
    }

    let _turn = scaffold_target_lock();
    let started = Instant::now();
    let out = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
        .arg("test")
        .arg("--manifest-path")
        .arg(dir.join("Cargo.toml"))
        .env("CARGO_TARGET_DIR", scaffold_target_dir())
        .output()
        .expect("cargo runs");
    let (stdout, stderr) = (text(&out.stdout), text(&out.stderr));
    assert!(
        out.status.success(),
        "`cargo test` in the scaffolded crate failed ({:?}, {:.0?}):\n{}\n{}",
        out.status,
        started.elapsed(),
        tail(&stderr, 60),
        tail(&stdout, 40)
    );
    assert!(
        stdout.contains("test tests::moves_its_entity_in_fixed_steps ... ok")
            && stdout.contains("test tests::its_state_survives_a_reload ... ok"),
        "the scaffolded tests did not run:\n{stdout}"
    );
}

#[test]
fn new_plugin_refuses_bad_names_and_existing_directories_with_exit_2() {
    let parent = tempfile::tempdir().unwrap();
    let parent_arg = parent.path().to_str().unwrap();
    for (name, why) in [
        ("9lives", "must start with a letter"),
        ("has space", "is not allowed"),
        ("fn", "keyword"),
    ] {
        let out = onyx(&["new-plugin", name, "--path", parent_arg]);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        let reason: Vec<&str> = err.lines().filter(|l| l.starts_with("onyx:")).collect();
        assert_eq!(reason.len(), 1, "{name}: {err}");
        assert!(reason[0].contains(why), "{name}: {err}");
        assert!(!parent.path().join(name).exists(), "{name} was created");
    }

    let existing = parent.path().join("taken");
    std::fs::create_dir(&existing).unwrap();
    std::fs::write(existing.join("notes.txt"), "mine").unwrap();
    let out = onyx(&["new-plugin", "taken", "--path", parent_arg]);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    let reason: Vec<&str> = err.lines().filter(|l| l.starts_with("onyx:")).collect();
    assert_eq!(reason.len(), 1, "{err}");
    assert!(reason[0].contains("already exists"), "{err}");
    assert_eq!(
        std::fs::read_dir(&existing).unwrap().count(),
        1,
        "the existing directory was touched"
    );

    // An empty directory is fine to fill.
    std::fs::create_dir(parent.path().join("empty")).unwrap();
    new_plugin("empty", parent.path());

    // ONYX_SOURCE_DIR picks the checkout the crate depends on, and must be one.
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
    let out = Command::new(onyx_binary())
        .args(["new-plugin", "elsewhere", "--path", parent_arg])
        .env("ONYX_SOURCE_DIR", parent.path())
        .output()
        .unwrap();
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("is not an Onyx checkout"), "{err}");
    assert!(!parent.path().join("elsewhere").exists());
    let out = Command::new(onyx_binary())
        .args(["new-plugin", "elsewhere", "--path", parent_arg])
        .env("ONYX_SOURCE_DIR", repo)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", text(&out.stderr));
    let manifest = std::fs::read_to_string(parent.path().join("elsewhere/Cargo.toml")).unwrap();
    let plugin_api = repo.canonicalize().unwrap().join("plugin-api");
    assert!(
        manifest.contains(&format!("path = \"{}\"", plugin_api.display())),
        "{manifest}"
    );

    let help = onyx(&["new-plugin", "--help"]);
    assert!(help.status.success());
    assert!(text(&help.stdout).contains("ONYX_SOURCE_DIR"));
    let help = onyx(&["dev", "--help"]);
    assert!(help.status.success());
    for flag in [
        "--plugin-crate",
        "--headless",
        "--frames",
        "--scene",
        "--set",
    ] {
        assert!(text(&help.stdout).contains(flag), "dev --help lacks {flag}");
    }
}

/// A running `onyx dev`, its stderr collected line by line; killed when dropped.
struct DevRun {
    child: Child,
    lines: Arc<Mutex<Vec<String>>>,
}

impl DevRun {
    fn start(crate_dir: &Path) -> Self {
        Self::start_all(&[crate_dir])
    }

    fn start_all(crate_dirs: &[&Path]) -> Self {
        let mut command = Command::new(onyx_binary());
        command.args(["dev", "--headless", "--frames", "100000"]);
        for dir in crate_dirs {
            command.arg("--plugin-crate").arg(dir);
        }
        let mut child = command
            .env("CARGO_TARGET_DIR", scaffold_target_dir())
            .env("RUST_LOG", "info")
            .env("NO_COLOR", "1")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .expect("onyx dev starts");
        let stderr = child.stderr.take().unwrap();
        let lines = Arc::new(Mutex::new(Vec::new()));
        let sink = lines.clone();
        std::thread::spawn(move || {
            for line in BufReader::new(stderr).lines() {
                let Ok(line) = line else { break };
                sink.lock().unwrap().push(line);
            }
        });
        Self { child, lines }
    }

    fn lines(&self) -> Vec<String> {
        self.lines.lock().unwrap().clone()
    }

    fn stderr_tail(&self) -> String {
        let lines = self.lines();
        lines[lines.len().saturating_sub(80)..].join("\n")
    }

    /// Waits until a line from index `from` on matches `pred`; returns its index and text.
    /// Fails, with what was seen, after `timeout` or when onyx exits.
    fn wait_for(
        &mut self,
        what: &str,
        from: usize,
        timeout: Duration,
        pred: impl Fn(&str) -> bool,
    ) -> (usize, String) {
        let deadline = Instant::now() + timeout;
        loop {
            let lines = self.lines();
            if let Some((i, line)) = lines.iter().enumerate().skip(from).find(|(_, l)| pred(l)) {
                return (i, line.clone());
            }
            if let Ok(Some(status)) = self.child.try_wait() {
                std::thread::sleep(Duration::from_millis(200)); // let the reader catch up
                panic!(
                    "onyx dev exited ({status}) before {what}; stderr:\n{}",
                    self.stderr_tail()
                );
            }
            assert!(
                Instant::now() < deadline,
                "no {what} within {timeout:?}; stderr:\n{}",
                self.stderr_tail()
            );
            std::thread::sleep(Duration::from_millis(50));
        }
    }
}

impl Drop for DevRun {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// `step N: travelled D m (speed S)` from the scaffolded plugin's log: steps, metres, speed.
fn progress(line: &str) -> Option<(u64, f32, f32)> {
    let rest = &line[line.find("step ")? + 5..];
    let (steps, rest) = rest.split_once(": travelled ")?;
    let (x, rest) = rest.split_once(" m (speed ")?;
    let (speed, _) = rest.split_once(')')?;
    Some((steps.parse().ok()?, x.parse().ok()?, speed.parse().ok()?))
}

/// `reloaded after N steps (speed S)`.
fn reloaded_after(line: &str) -> Option<(u64, f32)> {
    let rest = &line[line.find("reloaded after ")? + 15..];
    let (steps, rest) = rest.split_once(" steps (speed ")?;
    let (speed, _) = rest.split_once(')')?;
    Some((steps.parse().ok()?, speed.parse().ok()?))
}

fn edit(file: &Path, from: &str, to: &str) {
    let source = std::fs::read_to_string(file).unwrap();
    assert!(source.contains(from), "{} lacks {from}", file.display());
    std::fs::write(file, source.replace(from, to)).unwrap();
}

#[test]
fn dev_rebuilds_and_hot_reloads_a_scaffolded_plugin_on_save() {
    let parent = tempfile::tempdir().unwrap();
    let dir = new_plugin("fixture-dev-loop-probe", parent.path());
    let lib_rs = dir.join("src/lib.rs");
    let _turn = scaffold_target_lock();

    let mut dev = DevRun::start(&dir);
    // The first build compiles the Onyx crates for the scaffold (once per target directory).
    let (i, line) = dev.wait_for(
        "the plugin running at speed 1",
        0,
        Duration::from_secs(900),
        |l| progress(l).is_some_and(|(_, _, speed)| speed == 1.0),
    );
    let (steps_before, travelled_before, _) = progress(&line).unwrap();
    assert!(
        dev.lines()[..i]
            .iter()
            .any(|l| l.contains("loaded plugin library") && l.contains("fixture_dev_loop_probe")),
        "{}",
        dev.stderr_tail()
    );

    // Change the speed: rebuilt in the background, reloaded with its state.
    edit(
        &lib_rs,
        "pub const SPEED: f32 = 1.0;",
        "pub const SPEED: f32 = 2.0;",
    );
    let (r, _) = dev.wait_for("plugin reloaded", i, Duration::from_secs(300), |l| {
        l.contains("plugin reloaded")
    });
    let (_, line) = dev.wait_for(
        "the new build's reload message",
        i,
        Duration::from_secs(10),
        |l| reloaded_after(l).is_some(),
    );
    let (steps_at_reload, speed) = reloaded_after(&line).unwrap();
    assert_eq!(
        speed,
        2.0,
        "the new build attached: {line}\n{}",
        dev.stderr_tail()
    );
    assert!(
        steps_at_reload >= steps_before,
        "the step count was carried over ({steps_at_reload} < {steps_before}): {line}\n{}",
        dev.stderr_tail()
    );
    let (j, line) = dev.wait_for("progress at speed 2", r, Duration::from_secs(10), |l| {
        progress(l).is_some_and(|(_, _, speed)| speed == 2.0)
    });
    let (steps_after, travelled_after, _) = progress(&line).unwrap();
    assert!(
        steps_after > steps_at_reload && travelled_after > travelled_before,
        "state and world carried over: before {steps_before} steps {travelled_before} m, \
         after {steps_after} steps {travelled_after} m\n{}",
        dev.stderr_tail()
    );

    // A compile error: shown, and the running build keeps going.
    edit(
        &lib_rs,
        "pub const SPEED: f32 = 2.0;",
        "pub const SPEED: f32 = \"fast\";",
    );
    let (e, _) = dev.wait_for("the compiler's error", j, Duration::from_secs(300), |l| {
        l.contains("error[E0308]")
    });
    let (f, _) = dev.wait_for(
        "the failed build reported",
        e,
        Duration::from_secs(60),
        |l| l.contains("build failed") && l.contains("previous build keeps running"),
    );
    dev.wait_for(
        "progress after the failed build",
        f,
        Duration::from_secs(10),
        |l| progress(l).is_some_and(|(steps, _, speed)| speed == 2.0 && steps > steps_after),
    );
    assert!(
        !dev.lines().iter().any(|l| l.contains("faulted")),
        "{}",
        dev.stderr_tail()
    );

    // A build that crashes the host natively (it aborts as the loader opens it): the host
    // says which library, `onyx dev` keeps watching, and the next good build runs.
    const CRASH_ON_LOAD: &str = "
#[used]
#[link_section = \".init_array\"]
static CRASH_ON_LOAD: extern \"C\" fn() = {
    extern \"C\" fn crash() {
        std::process::abort()
    }
    crash
};
";
    edit(
        &lib_rs,
        "pub const SPEED: f32 = \"fast\";",
        &format!("pub const SPEED: f32 = 2.5;{CRASH_ON_LOAD}"),
    );
    let (c, line) = dev.wait_for("the crash line", f, Duration::from_secs(300), |l| {
        l.starts_with("onyx: native crash: SIGABRT")
    });
    assert!(
        line.contains("in the library `") && line.contains("(loading)"),
        "{line}"
    );
    let (w, _) = dev.wait_for("onyx dev still watching", c, Duration::from_secs(10), |l| {
        l.contains("the host stopped (exit status 3)") && l.contains("still watching")
    });
    assert!(
        dev.child.try_wait().unwrap().is_none(),
        "onyx dev outlives the host"
    );
    edit(
        &lib_rs,
        &format!("pub const SPEED: f32 = 2.5;{CRASH_ON_LOAD}"),
        "pub const SPEED: f32 = 4.0;",
    );
    let (s, _) = dev.wait_for("the host started again", w, Duration::from_secs(300), |l| {
        l.contains("starting the host again")
    });
    dev.wait_for("the fixed build running", s, Duration::from_secs(30), |l| {
        progress(l).is_some_and(|(_, _, speed)| speed == 4.0)
    });
    assert!(
        dev.child.try_wait().unwrap().is_none(),
        "onyx dev is still running"
    );
    drop(dev);

    // A first build that fails: exit 2 with one line, after the compiler's errors.
    edit(
        &lib_rs,
        "pub const SPEED: f32 = 4.0;",
        "pub const SPEED: f32 = \"fast\";",
    );
    let dev_once = |frames: &str| {
        Command::new(onyx_binary())
            .args(["dev", "--headless", "--frames", frames, "--plugin-crate"])
            .arg(&dir)
            .env("CARGO_TARGET_DIR", scaffold_target_dir())
            .env("RUST_LOG", "warn")
            .env("NO_COLOR", "1")
            .output()
            .expect("onyx dev runs")
    };
    let out = dev_once("3");
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{}", tail(&err, 60));
    let reason: Vec<&str> = err.lines().filter(|l| l.starts_with("onyx:")).collect();
    assert_eq!(reason.len(), 1, "{err}");
    assert!(reason[0].contains("`cargo build` failed"), "{err}");
    assert!(err.contains("error[E0308]"), "{err}");

    // Fixed: it builds, runs its frames and ends cleanly.
    edit(
        &lib_rs,
        "pub const SPEED: f32 = \"fast\";",
        "pub const SPEED: f32 = 3.0;",
    );
    let out = dev_once("5");
    assert!(
        out.status.success(),
        "exit {:?}: {}",
        out.status,
        tail(&text(&out.stderr), 60)
    );
}

/// The crate `fixture-dev-graph-shared`: the speed and part of the state of two plugins.
const SHARED_LIB_RS: &str = r#"//! Game code two plugins share: their speed and a part of their state.

/// How fast the plugins move their entities, metres per second.
pub const SPEED: f32 = 1.0;

/// What the plugins carry in their state.
#[derive(Debug, Default, serde::Serialize, serde::Deserialize)]
pub struct Tally {
    /// Laps run.
    pub laps: u64,
}
"#;

/// A scaffolded plugin whose speed and part of whose state come from `../shared`.
fn plugin_on_shared(name: &str, parent: &Path) -> PathBuf {
    let dir = new_plugin(name, parent);
    edit(
        &dir.join("Cargo.toml"),
        "[dependencies]\n",
        "[dependencies]\nfixture-dev-graph-shared = { path = \"../shared\" }\n",
    );
    let lib_rs = dir.join("src/lib.rs");
    edit(
        &lib_rs,
        "pub const SPEED: f32 = 1.0;",
        "pub const SPEED: f32 = fixture_dev_graph_shared::SPEED;",
    );
    edit(
        &lib_rs,
        "    pub cube: Option<Entity>,\n",
        "    pub cube: Option<Entity>,\n    #[serde(default)]\n    pub tally: fixture_dev_graph_shared::Tally,\n",
    );
    dir
}

#[test]
fn dev_rebuilds_and_swaps_every_plugin_that_depends_on_an_edited_crate() {
    let parent = tempfile::tempdir().unwrap();
    let shared = parent.path().join("shared");
    std::fs::create_dir_all(shared.join("src")).unwrap();
    std::fs::write(
        shared.join("Cargo.toml"),
        "[package]\nname = \"fixture-dev-graph-shared\"\nversion = \"0.1.0\"\nedition = \"2021\"\n\
         publish = false\n\n[dependencies]\nserde = { version = \"1\", features = [\"derive\"] }\n",
    )
    .unwrap();
    let shared_rs = shared.join("src/lib.rs");
    std::fs::write(&shared_rs, SHARED_LIB_RS).unwrap();
    let a = plugin_on_shared("fixture-dev-graph-a", parent.path());
    let b = plugin_on_shared("fixture-dev-graph-b", parent.path());
    let _turn = scaffold_target_lock();

    let mut dev = DevRun::start_all(&[&a, &b]);
    let running_at = |speed: f32, plugin: &'static str| {
        move |l: &str| l.contains(plugin) && progress(l).is_some_and(|(_, _, s)| s == speed)
    };
    let (i, line) = dev.wait_for(
        "plugin a at speed 1",
        0,
        Duration::from_secs(900),
        running_at(1.0, "fixture_dev_graph_a"),
    );
    let (a_steps, _, _) = progress(&line).unwrap();
    dev.wait_for(
        "plugin b at speed 1",
        0,
        Duration::from_secs(60),
        running_at(1.0, "fixture_dev_graph_b"),
    );
    assert!(
        dev.lines()
            .iter()
            .any(|l| l.contains("fixture-dev-graph-shared")),
        "the shared crate is not watched:\n{}",
        dev.stderr_tail()
    );

    // The shared crate changes the speed and adds a field to the state: both plugins are
    // rebuilt in one round and swap in one frame, their state kept.
    let source = std::fs::read_to_string(&shared_rs).unwrap();
    let edited = source
        .replace("pub const SPEED: f32 = 1.0;", "pub const SPEED: f32 = 2.0;")
        .replace(
            "    pub laps: u64,\n",
            "    pub laps: u64,\n    /// The best lap.\n    #[serde(default)]\n    pub best: u32,\n",
        );
    assert_ne!(source, edited);
    std::fs::write(&shared_rs, edited).unwrap();
    let (r, _) = dev.wait_for("one swap of both", i, Duration::from_secs(300), |l| {
        l.contains("2 of 2 rebuilt plugins swapped in one frame")
    });
    assert!(
        dev.lines()[i..r]
            .iter()
            .any(|l| l.contains("rebuilding 2 plugin crates together")),
        "{}",
        dev.stderr_tail()
    );
    for plugin in ["fixture_dev_graph_a", "fixture_dev_graph_b"] {
        let (_, line) = dev.wait_for("a reload message", i, Duration::from_secs(10), |l| {
            l.contains(plugin) && reloaded_after(l).is_some()
        });
        let (steps, speed) = reloaded_after(&line).unwrap();
        assert_eq!(speed, 2.0, "{line}");
        assert!(steps >= a_steps, "{plugin} lost its state: {line}");
    }
    let (j, _) = dev.wait_for(
        "progress at speed 2",
        r,
        Duration::from_secs(10),
        running_at(2.0, "fixture_dev_graph_b"),
    );

    // A type serde cannot map: both swaps are refused with one sentence each, and the
    // running builds go on.
    edit(&shared_rs, "pub laps: u64,", "pub laps: String,");
    for plugin in ["fixture_dev_graph_a", "fixture_dev_graph_b"] {
        let (_, line) = dev.wait_for("the refusal", j, Duration::from_secs(300), |l| {
            l.contains(&format!("plugin `{plugin}` was not reloaded"))
        });
        assert!(
            line.contains("cannot read the state of the running one")
                && line.contains("at `tally.laps`: invalid type: integer `0`, expected a string")
                && line.contains("the previous build keeps running"),
            "{line}"
        );
    }
    let (k, _) = dev.wait_for("the refusals reported", j, Duration::from_secs(10), |l| {
        l.contains("0 of 2 rebuilt plugins swapped in one frame")
    });
    dev.wait_for(
        "the old builds running on",
        k,
        Duration::from_secs(10),
        running_at(2.0, "fixture_dev_graph_a"),
    );
    assert!(
        !dev.lines().iter().any(|l| l.contains("faulted")),
        "{}",
        dev.stderr_tail()
    );
}
