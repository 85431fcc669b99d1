#!/usr/bin/env bash
# Runs every check and test, from a fresh clone on a fresh Debian 12 machine:
# system packages (scripts/setup.sh), formatting, lints, the plugin libraries, all tests.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/setup.sh
unset WAYLAND_DISPLAY
# The build settings (no incremental caches, line tables only) are the workspace's, in
# Cargo.toml's [profile.dev]: scripts/run.sh and a plain `cargo build` use the same ones, so
# neither compiles again what this script built, nor this script what they built.
# Disk and temp space at the end, pass or fail: plugin loads copy libraries into the temp
# folder and the scaffold test builds a second crate, so a full disk shows up as failures.
trap 'df -h . "${TMPDIR:-/tmp}" >&2' EXIT

cargo fmt --all --check
cargo clippy --workspace --all-targets --locked -- -D warnings
# The end-to-end tests load the plugin cdylibs and run the `onyx` binary from the target
# directory: build them first (a nested `cargo build` inside a test would wait on cargo's lock).
# onyx_build (scripts/setup.sh) is scripts/run.sh's build too; it builds the test targets in
# the same invocation, so dev-dependencies unify features once and `cargo test` below
# compiles nothing again.
onyx_build
echo "test.sh: the end-to-end tests run $PWD/target/debug/onyx and the plugin libraries beside it" >&2
# Windows (winit) and rendering (wgpu on Mesa's CPU Vulkan) are tested for real: under Xvfb.
xvfb-run -a -s "-screen 0 1280x720x24" cargo test --workspace --locked
