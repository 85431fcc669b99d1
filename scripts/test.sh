#!/usr/bin/env bash
# Runs every check and test, from a fresh clone on a fresh Debian 12 machine:
# system packages (scripts/setup.sh), formatting, lints, the plugin libraries, all tests.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/setup.sh
unset WAYLAND_DISPLAY

cargo fmt --all --check
cargo clippy --workspace --all-targets --locked -- -D warnings
# The end-to-end tests load the plugin cdylibs and run the `onyx` binary from the target
# directory: build them first (a nested `cargo build` inside a test would wait on cargo's lock).
cargo build --workspace --locked
# Windows (winit) and rendering (wgpu on Mesa's CPU Vulkan) are tested for real: under Xvfb.
xvfb-run -a -s "-screen 0 1280x720x24" cargo test --workspace --locked
