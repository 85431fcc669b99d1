#!/usr/bin/env bash
# Installs what Onyx needs on Debian/Ubuntu, once: the system packages winit loads at run
# time (X11), Xvfb for a window without a display, and Mesa's CPU Vulkan driver (lavapipe)
# for rendering without a GPU; x11-utils (xwininfo) lets the tests read window titles.
# Sourced by scripts/test.sh and scripts/run.sh.
set -euo pipefail

ONYX_PACKAGES=(
  mesa-vulkan-drivers libvulkan1 libgl1-mesa-dri libegl1
  xvfb xauth libx11-xcb1 libxcursor1 libxi6 libxrandr2 libxkbcommon-x11-0
  x11-utils
)

onyx_missing_packages() {
  local missing=()
  for p in "${ONYX_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  echo "${missing[@]:-}"
}

if command -v dpkg-query >/dev/null 2>&1; then
  missing="$(onyx_missing_packages)"
  if [ -n "$missing" ]; then
    echo "onyx setup: installing system packages: $missing" >&2
    SUDO=""
    if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
    $SUDO apt-get update -qq
    # shellcheck disable=SC2086
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing >/dev/null
  fi
else
  echo "onyx setup: not a Debian-like system; install the equivalents of: ${ONYX_PACKAGES[*]}" >&2
fi

if ! command -v cargo >/dev/null 2>&1; then
  echo "onyx setup: cargo not found; install Rust (https://rustup.rs) and retry" >&2
  exit 1
fi

# The one build every script runs (run.sh, test.sh, example.sh): the libraries, binaries,
# tests and examples of the whole workspace, with the settings of Cargo.toml's [profile.dev].
# The same command each time builds the same crates with the same features (the tests'
# dev-dependencies turn features on in shared dependencies, so a build without the tests
# compiles the crates above those a second time), so after any of the scripts the others
# compile nothing again.
onyx_build() {
  cargo build --workspace --locked --lib --bins --tests --examples "$@"
}

# Rendering and windows without a GPU: Mesa's CPU Vulkan driver, X11 only.
export WGPU_BACKEND="${WGPU_BACKEND:-vulkan}"
export WGPU_ADAPTER_NAME="${WGPU_ADAPTER_NAME:-llvmpipe}"
if [ -z "${XDG_RUNTIME_DIR:-}" ]; then
  XDG_RUNTIME_DIR="$(mktemp -d)"
  export XDG_RUNTIME_DIR
fi
