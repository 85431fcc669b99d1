//! Running the `onyx` binary from a test and reading what it said: the exit status and the
//! `onyx:` lines (one sentence per reason) on stderr.

use std::process::{Command, Output};

use crate::{onyx_binary, target_dir};

/// `onyx ARGS…` with this build's plugins on the search path, warnings logged, and its output
/// collected.
pub fn onyx(args: &[&str]) -> Output {
    Command::new(onyx_binary())
        .args(args)
        .env("ONYX_PLUGIN_PATH", target_dir())
        .env("RUST_LOG", "warn")
        .output()
        .expect("onyx runs")
}

/// What the process wrote on stderr, as text.
pub fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// The `onyx:` lines on stderr: the reasons the command line gives, one sentence each.
pub fn onyx_lines(out: &Output) -> Vec<String> {
    stderr(out)
        .lines()
        .filter(|l| l.starts_with("onyx:"))
        .map(str::to_owned)
        .collect()
}

/// Asserts the process exited with `code`, showing its stderr when it did not.
#[track_caller]
pub fn assert_exit(out: &Output, code: i32) {
    assert_eq!(out.status.code(), Some(code), "{}", stderr(out));
}
