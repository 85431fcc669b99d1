#!/usr/bin/env bash
# Lists the examples (examples/README.md has a lesson for each), or builds and runs one:
#   bash scripts/example.sh                    # the list
#   bash scripts/example.sh NAME [ARGS...]     # run example NAME; ARGS go to `onyx run`
# The build is scripts/run.sh's and scripts/test.sh's (onyx_build in scripts/setup.sh):
# after any of them, nothing compiles again. Without a display the example runs under Xvfb (for 300 frames when no
# ARGS are given).
set -euo pipefail
cd "$(dirname "$0")/.."

# name | plugins to load | one line on what it shows
EXAMPLES=(
  "first-plugin|first_plugin|a lit, spinning cube and a camera: the shape of a plugin"
  "camera-controller|camera_controller|WASD + right mouse fly camera: reading input"
  "gui-spawner|gui_spawner|an egui window whose buttons spawn falling bodies"
  "events|events_ping events_pong|two plugins talking through custom events"
  "physics-playground|physics_playground|forces (arrow keys, Space), click to shove, contact events"
  "joints|joints|a swinging door, a chain, a ragdoll and a trigger zone: Joint components and a sensor"
  "character|character|a capsule walked over stairs and ramps (WASD/arrows, Space jumps): the character controller"
  "procedural-mesh|procedural_mesh|a height field generated in code, drawn and collided with"
  "tested-plugin|tested_plugin|a plugin and its headless tests (cargo test -p tested-plugin)"
  "hot-reload|hot_reload|what survives a reload; try it with: target/debug/onyx dev --plugin-crate examples/hot-reload"
)

if [ "$#" -eq 0 ]; then
  echo "examples (bash scripts/example.sh NAME to run one; lessons in examples/README.md):"
  for entry in "${EXAMPLES[@]}"; do
    IFS='|' read -r name _ what <<<"$entry"
    printf '  %-20s %s\n' "$name" "$what"
  done
  exit 0
fi

wanted="$1"
shift
plugins=""
for entry in "${EXAMPLES[@]}"; do
  IFS='|' read -r name libs _ <<<"$entry"
  if [ "$name" = "$wanted" ]; then plugins="$libs"; fi
done
if [ -z "$plugins" ]; then
  echo "example.sh: no example \`$wanted\`; run it without arguments for the list" >&2
  exit 2
fi

source scripts/setup.sh
onyx_build
ONYX="$PWD/target/debug/onyx"
echo "example.sh: running $ONYX" >&2
ARGS=(run)
for plugin in $plugins; do ARGS+=(--plugin "$plugin"); done

if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] || [[ " $* " == *" --headless "* ]]; then
  exec "$ONYX" "${ARGS[@]}" "$@"
elif [ "$#" -gt 0 ]; then
  exec xvfb-run -a -s "-screen 0 1280x720x24" "$ONYX" "${ARGS[@]}" "$@"
else
  echo "example.sh: no display; running the window under Xvfb for 300 frames" >&2
  exec xvfb-run -a -s "-screen 0 1280x720x24" "$ONYX" "${ARGS[@]}" --frames 300
fi
