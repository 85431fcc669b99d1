#!/usr/bin/env bash
# Builds Onyx and runs the host with the example plugins (showcase: every shading mode, a
# textured model, falling bodies; spinner: the demo scene's cubes spinning) and the demo scene.
# With a display: a window until you close it. Without one: the same under Xvfb for
# 300 frames, then a screenshot is saved to target/demo.png and the world to
# target/demo-state.json.
# Extra arguments go to `onyx run` (e.g. `scripts/run.sh --headless --frames 60`).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/setup.sh

# The build scripts/test.sh runs too (onyx_build, scripts/setup.sh): after either script,
# the other compiles nothing again.
onyx_build
ONYX="$PWD/target/debug/onyx"
echo "run.sh: running $ONYX" >&2
DEMO=(run --plugin showcase --plugin spinner --scene assets/scenes/demo.ron)

if [ "$#" -gt 0 ]; then
  exec "$ONYX" "${DEMO[@]}" "$@"
elif [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$ONYX" "${DEMO[@]}"
else
  echo "onyx: no display; running the window under Xvfb for 300 frames" >&2
  exec xvfb-run -a -s "-screen 0 1280x720x24" \
    "$ONYX" "${DEMO[@]}" --frames 300 --dump-state target/demo-state.json \
    --screenshot target/demo.png
fi
