#!/usr/bin/env bash
# The viewer's frame rate as a user meets it: `vkpt --interactive` on SCENE in a virtual X
# server (Xvfb), the camera dragged in circles for SECONDS with xdotool (XTEST), then left at
# rest for REST seconds, then Escape. vkpt's closing summary gives the frames a second
# while the camera moved (a quarter-size, 1-spp render each, shown in the window) and at
# rest (full size, accumulating), and the time from launch to the first picture. One run
# per backend; the figures are in bench/README.md, "Viewer".
# Usage (after `cmake -B build && cmake --build build`; needs xvfb and xdotool):
#   bash bench/viewer.sh [SCENE [SIZE [SECONDS [REST]]]]   defaults: scenes/cornell.gltf 512 10 5
# VKPT_BUILD names another build folder (default build).
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-scenes/cornell.gltf} size=${2:-512} seconds=${3:-10} rest=${4:-5} build=${VKPT_BUILD:-build}
title="vkpt: $(basename "$scene")"
for tool in Xvfb xdotool xwininfo; do
  command -v "$tool" > /dev/null || { echo "bench/viewer.sh: $tool is missing (apt-get install xvfb xdotool x11-utils)" >&2; exit 1; }
done
display=:$((RANDOM % 400 + 100))
Xvfb "$display" -screen 0 "$((size + 64))x$((size + 64))x24" -nolisten tcp > /dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2> /dev/null || true' EXIT
export DISPLAY=$display
unset WAYLAND_DISPLAY
for _ in $(seq 50); do xdpyinfo > /dev/null 2>&1 && break || sleep 0.2; done

# rss PID: its resident memory, "N MiB".
rss() { awk '/^VmRSS/ {printf "%.0f MiB", $2 / 1024}' "/proc/$1/status"; }

for backend in vulkan cpu; do
  out=$(mktemp)
  "$build/vkpt" --scene "$scene" --interactive --backend "$backend" --width "$size" --height "$size" \
    > "$out" 2>&1 &
  vkpt=$!
  for _ in $(seq 300); do xwininfo -name "$title" > /dev/null 2>&1 && break || sleep 0.2; done
  sleep 2  # the first full-size frames
  before=$(rss "$vkpt")
  centre=$((size / 2)) radius=$((size / 4)) end=$((SECONDS + seconds)) step=0
  xdotool mousemove "$centre" "$centre" mousedown 1
  while [ "$SECONDS" -lt "$end" ]; do
    step=$((step + 1))
    # A circle of 36 points, a point every 20 ms: the camera never rests.
    x=$(awk -v c="$centre" -v r="$radius" -v k="$step" 'BEGIN {printf "%d", c + r * cos(k * 3.14159 / 18)}')
    y=$(awk -v c="$centre" -v r="$radius" -v k="$step" 'BEGIN {printf "%d", c + r * sin(k * 3.14159 / 18)}')
    xdotool mousemove "$x" "$y"
    sleep 0.02
  done
  xdotool mouseup 1
  moved=$(rss "$vkpt")
  sleep "$rest"
  rested=$(rss "$vkpt")
  xdotool mousemove "$centre" "$centre" key Escape
  wait "$vkpt"
  echo "$(basename "$scene"), $backend, $size x $size: $(grep 'viewer closed' "$out")"
  echo "  resident memory: $before before the drag, $moved after it ($step moves), $rested at rest"
  rm -f "$out"
done
