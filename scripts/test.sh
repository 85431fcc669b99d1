#!/usr/bin/env bash
# Runs every check and test, from a fresh clone on a fresh Debian 12 machine:
# system packages (scripts/setup.sh), formatting, lints, the plugin libraries, all tests.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/setup.sh
unset WAYLAND_DISPLAY
# Each crate is built once per run: incremental caches would only cost disk (gigabytes,
# on machines that may have little) and time.
export CARGO_INCREMENTAL=0
# Line tables only for the workspace's own crates (dependencies have none, see Cargo.toml):
# backtraces and panic locations keep file:line, the target directory shrinks by gigabytes.
export CARGO_PROFILE_DEV_DEBUG=line-tables-only
# Disk and temp space at the end, pass or fail: plugin loads copy libraries into the temp
# folder and the scaffold test builds a second crate, so a full disk shows up as failures.
trap 'df -h . "${TMPDIR:-/tmp}" >&2' EXIT

cargo fmt --all --check
cargo clippy --workspace --all-targets --locked -- -D warnings
# The end-to-end tests load the plugin cdylibs and run the `onyx` binary from the target
# directory: build them first (a nested `cargo build` inside a test would wait on cargo's lock).
# The test targets are built in the same invocation, so dev-dependencies unify features once
# and `cargo test` below compiles nothing again.
cargo build --workspace --locked --lib --bins --tests --examples
# Windows (winit) and rendering (wgpu on Mesa's CPU Vulkan) are tested for real: under Xvfb.
xvfb-run -a -s "-screen 0 1280x720x24" cargo test --workspace --locked
