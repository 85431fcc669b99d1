//! What the host can only report: native crashes (segfault, abort, stack overflow), a plugin
//! ending the process with `exit`, and calls that do not return. The `onyx` binary with a real
//! cdylib that fails on purpose (`tests/fixtures/native`).

use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use onyx_runtime::watchdog::{EXIT_NATIVE_CRASH, EXIT_PLUGIN_EXITED};
use onyx_tests::cli::{onyx_lines, stderr};
use onyx_tests::{onyx_binary, target_dir};

const NATIVE: &str = "fixture_native";

fn onyx_with(settings: &[(&str, &str)], extra: &[&str]) -> Command {
    let mut command = Command::new(onyx_binary());
    command
        .args(["run", "--headless", "--frames", "4", "--plugin", NATIVE])
        .args(extra)
        .env("ONYX_PLUGIN_PATH", target_dir())
        .env("RUST_LOG", "info");
    for (key, value) in settings {
        command.args(["--set", &format!("{NATIVE}.{key}={value}")]);
    }
    command
}

fn run(settings: &[(&str, &str)], extra: &[&str]) -> Output {
    onyx_with(settings, extra).output().expect("onyx runs")
}

#[test]
fn native_crashes_name_the_plugin_and_stage_and_exit_with_their_own_status() {
    let cases = [
        ("segfault", "on_update", "SIGSEGV"),
        ("stack_overflow", "on_update", "SIGSEGV"),
        ("abort", "on_update", "SIGABRT"),
        ("segfault", "on_fixed_update", "SIGSEGV"),
        ("abort", "on_attach", "SIGABRT"),
    ];
    for (fail, stage, signal) in cases {
        let dir = tempfile::tempdir().unwrap();
        let dump = dir.path().join("dump.json");
        let out = run(
            &[("fail", fail), ("in", stage)],
            &["--dump-state", dump.to_str().unwrap()],
        );
        assert_eq!(
            out.status.code(),
            Some(i32::from(EXIT_NATIVE_CRASH)),
            "{fail} in {stage}: {}",
            stderr(&out)
        );
        let lines = onyx_lines(&out);
        assert_eq!(lines.len(), 1, "{fail} in {stage}: one line: {lines:?}");
        let expected_place = format!("in plugin `{NATIVE}` ({stage})");
        assert!(
            lines[0].starts_with(&format!("onyx: native crash: {signal} "))
                && lines[0].contains(&expected_place)
                && lines[0].ends_with("the process ends with status 3"),
            "{fail} in {stage}: {}",
            lines[0]
        );
        assert!(!dump.exists(), "a crashed run writes no dump");
    }
}

#[test]
fn a_plugin_calling_exit_is_not_a_clean_run() {
    let dir = tempfile::tempdir().unwrap();
    let dump = dir.path().join("dump.json");
    let out = run(
        &[("fail", "exit"), ("in", "on_update"), ("at", "2")],
        &["--dump-state", dump.to_str().unwrap()],
    );
    assert_eq!(
        out.status.code(),
        Some(i32::from(EXIT_PLUGIN_EXITED)),
        "{}",
        stderr(&out)
    );
    let lines = onyx_lines(&out);
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].contains(&format!(
            "ended by a call to exit in plugin `{NATIVE}` (on_update)"
        )) && lines[0].contains("nothing was saved or dumped"),
        "{}",
        lines[0]
    );
    assert!(!dump.exists());

    // The host's own ending is not mistaken for one.
    let out = run(&[], &[]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(onyx_lines(&out).is_empty(), "{}", stderr(&out));
}

#[test]
fn the_watchdog_reports_a_call_that_does_not_return_and_when_it_does() {
    for fail in ["sleep", "spin"] {
        let out = run(
            &[("fail", fail), ("seconds", "1.6"), ("in", "on_update")],
            &["--watchdog", "0.4"],
        );
        let text = stderr(&out);
        assert!(out.status.success(), "{fail}: the run goes on: {text}");
        let stuck: Vec<&str> = text
            .lines()
            .filter(|l| l.contains(&format!("plugin `{NATIVE}` has been running on_update for")))
            .collect();
        assert_eq!(
            stuck.len(),
            1,
            "{fail}: reported once (repeats are 10 s apart): {text}"
        );
        assert!(
            stuck[0].contains("WARN") && stuck[0].contains("cannot be stopped safely"),
            "{}",
            stuck[0]
        );
        assert!(
            text.contains(&format!("plugin `{NATIVE}` returned from on_update after")),
            "{fail}: {text}"
        );
    }

    // Off by flag.
    let out = run(
        &[("fail", "sleep"), ("seconds", "1.0")],
        &["--watchdog", "0"],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        !stderr(&out).contains("has been running"),
        "{}",
        stderr(&out)
    );
}

/// The titles of the X server's windows, as `xwininfo` lists them.
fn window_titles() -> Option<String> {
    let out = Command::new("xwininfo")
        .args(["-root", "-tree"])
        .output()
        .ok()?;
    Some(String::from_utf8_lossy(&out.stdout).into_owned())
}

#[test]
fn a_stuck_call_shows_in_the_window_title() {
    if std::env::var_os("DISPLAY").is_none() || window_titles().is_none() {
        eprintln!("skipped: needs an X display and xwininfo (the README's test command has both)");
        return;
    }
    let mut child = Command::new(onyx_binary())
        .args([
            "run",
            "--frames",
            "6",
            "--plugin",
            NATIVE,
            "--watchdog",
            "0.3",
        ])
        .args(["--set", &format!("{NATIVE}.fail=sleep")])
        .args(["--set", &format!("{NATIVE}.seconds=4")])
        .args(["--set", &format!("{NATIVE}.at=2")])
        .env("ONYX_PLUGIN_PATH", target_dir())
        .env_remove("WAYLAND_DISPLAY")
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("onyx runs");
    let deadline = Instant::now() + Duration::from_secs(60);
    let mut seen = String::new();
    while Instant::now() < deadline {
        let titles = window_titles().unwrap_or_default();
        if titles.contains(&format!(
            "not responding: plugin `{NATIVE}` has been running on_update"
        )) {
            seen = titles;
            break;
        }
        if child.try_wait().expect("can wait").is_some() {
            break;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    let out = child.wait_with_output().expect("onyx ends");
    assert!(
        !seen.is_empty(),
        "the title never said so; stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
