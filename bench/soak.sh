#!/usr/bin/env bash
# Soak: does vkpt's memory hold over long work? Three runs on the Cornell box, each
# printing its resident memory (RSS) and peak (HWM) at ten points and a last line:
#   1. one render of --time SECONDS on the Vulkan device (lavapipe here), 64²;
#   2. RENDERS Python renders of one vkpt.Scene, 32² at 1 spp, with the C heap in use;
#   3. a --frames sequence of FRAMES frames, 16² at 1 spp, turning 360° in all.
# Usage (after `cmake -B build && cmake --build build`):
#   bash bench/soak.sh [SECONDS [RENDERS [FRAMES]]]     defaults: 600 10000 10000 (~13 min)
# VKPT_BUILD names another build folder (default build), e.g. one of an earlier commit.
# The figures of a run before and after a change are in bench/README.md, "Soak".
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600} renders=${2:-10000} frames=${3:-10000} build=${VKPT_BUILD:-build}
scene=scenes/cornell.gltf
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# status PID: "rss N MiB, peak N MiB" from /proc/PID/status (empty once it has exited).
status() {
  awk '/^VmRSS/ {rss = $2} /^VmHWM/ {hwm = $2}
       END {if (rss) printf "rss %6.1f MiB, peak %6.1f MiB", rss / 1024, hwm / 1024}' "/proc/$1/status" 2> /dev/null || true
}

# watch LABEL COUNT-COMMAND COMMAND...: runs COMMAND in the background and prints its
# memory at ten even points of its expected length, with what COUNT-COMMAND counts then.
watch() {
  local label=$1 count=$2 expected=$3
  shift 3
  "$@" > "$work/out.txt" 2>&1 &
  local pid=$! start=$SECONDS step=$(((expected + 9) / 10))
  local next=$step
  while kill -0 "$pid" 2> /dev/null; do
    sleep 1
    if [ $((SECONDS - start)) -ge "$next" ]; then
      local s  # of the program /usr/bin/time runs
      s=$(status "$(pgrep -P "$pid" | head -1)")
      if [ -n "$s" ]; then printf '  %-8s %5d s  %-14s %s\n' "$label" $((SECONDS - start)) "$(eval "$count")" "$s"; fi
      next=$((next + step))
    fi
  done
  wait "$pid" || { cat "$work/out.txt"; exit 1; }
}

echo "soak: one render of --time $seconds s, 64², on the Vulkan device"
watch render "echo render" "$seconds" \
  /usr/bin/time -f 'peak %M KiB' -o "$work/time.txt" \
  "$build/vkpt" --scene "$scene" --backend vulkan --width 64 --height 64 --time "$seconds" --spp 1073741824 \
  --out "$work/render.png"  # the most --spp allows: the time ends the render, not its 65,536 spp default
grep -E 'spp|stopped by' "$work/out.txt" | sed 's/^/  /'
echo "  render   done: $(awk '{printf "peak %.1f MiB", $2 / 1024}' "$work/time.txt")"

echo "soak: $renders Python renders of one vkpt.Scene, 32² at 1 spp"
PYTHONPATH="$build/python" python3 - "$scene" "$renders" << 'EOF'
import ctypes, sys, time
import vkpt

class MallInfo2(ctypes.Structure):
    _fields_ = [(n, ctypes.c_size_t) for n in
                ("arena", "ordblks", "smblks", "hblks", "hblkhd", "usmblks", "fsmblks", "uordblks", "fordblks", "keepcost")]
libc = ctypes.CDLL("libc.so.6")
libc.mallinfo2.restype = MallInfo2

def status():
    fields = dict(line.split(":", 1) for line in open("/proc/self/status"))
    mib = lambda key: int(fields[key].split()[0]) / 1024
    m = libc.mallinfo2()
    return "rss %6.1f MiB, peak %6.1f MiB, heap in use %6.1f MiB" % (mib("VmRSS"), mib("VmHWM"),
                                                                      (m.uordblks + m.hblkhd) / 2**20)

scene, n = vkpt.Scene(sys.argv[1], backend="vulkan"), int(sys.argv[2])
start = time.monotonic()
for i in range(1, n + 1):
    scene.render(width=32, height=32, spp=1, chunk_spp=1)
    if i % max(n // 10, 1) == 0:
        print("  %-8s %5d s  %-14s %s" % ("python", time.monotonic() - start, "render %d" % i, status()), flush=True)
EOF

echo "soak: a sequence of $frames frames, 16² at 1 spp"
# About 3 ms a frame on lavapipe: the expected length sets the points of the report.
watch frames "echo frame \$(ls $work | grep -c '^f\\.')" $((frames * 3 / 1000 + 1)) \
  /usr/bin/time -f 'peak %M KiB' -o "$work/time.txt" \
  "$build/vkpt" --scene "$scene" --backend vulkan --width 16 --height 16 --spp 1 \
  --orbit "$(awk "BEGIN {print 360 / $frames}")" --frames "0:$((frames - 1))" --out "$work/f.png"
echo "  frames   done: $(awk '{printf "peak %.1f MiB", $2 / 1024}' "$work/time.txt")"
