#!/usr/bin/env bash
# Regenerates bench/README.md from fresh measurements on this machine:
#   bash bench/run.sh            (after `cmake -B build && cmake --build build`)
set -euo pipefail
cd "$(dirname "$0")/.."
bench=build/vkpt-bench
corpus=../shared/gltf-corpus/valid
out=bench/README.md
ref=bench/data/cornell-ref-16k.pfm
rows=()
engine="$corpus/2CylinderEngine/glTF-Binary/2CylinderEngine.glb"
for threads in 1 2; do
  rows+=("$($bench --procedural 1000000 --threads $threads --markdown)")
  rows+=("$($bench --scene scenes/cornell.gltf --threads $threads --markdown)")
  if [ -f "$engine" ]; then rows+=("$($bench --scene "$engine" --threads $threads --markdown)"); fi
done
# Spatial splits (--splits spatial), one thread.
rows+=("$($bench --procedural 1000000 --threads 1 --splits spatial --markdown)")
if [ -f "$engine" ]; then rows+=("$($bench --scene "$engine" --threads 1 --splits spatial --markdown)"); fi
quality=""
if [ -f "$ref" ]; then
  quality="$($bench --scene scenes/cornell.gltf --quality "$ref" --threads 2 2>/dev/null)"
fi
{
  cat <<'HEAD'
# Benchmarks

`build/vkpt-bench` traces the same rays with every tracer vkpt has — the CPU reference's
ordered stack traversal, the GLSL stackless traversal (trace.comp) on the Vulkan device —
and with Intel Embree 3 (`rtcIntersect1`, build quality MEDIUM) when it was found at
configure time; it cross-checks their closest hits and reports full path-tracing rates.

```sh
build/vkpt-bench --procedural 1000000 --threads 1          # human-readable, with % of Embree
build/vkpt-bench --scene scenes/cornell.gltf --json         # one JSON object
bash bench/run.sh                                           # regenerates this file
```

Rays: 1024×1024 camera rays through pixel centres, then one cosine-weighted bounce from
every hit ("diffuse"). Mrays/s; path tracing in Msamples/s at 256×256 × 16 spp, max depth
32. `--threads` applies to every tracer (CPU threads, Embree's thread count, and
`LP_NUM_THREADS` for lavapipe). "mismatches": rays whose hit distance differs between
tracers by more than 1e-4 relative (grazing hits on shared edges). Build rates are the
best of three builds, vkpt's with `--threads` threads and Embree's (BUILD_QUALITY_MEDIUM)
with one; `--json` also gives vkpt's one-thread rate from the same run
(`build_mtris_per_s_1t`) and the run's peak host memory (`peak_rss_mib`: scene, trees,
ray sets, lavapipe and Embree together; "GPU bytes per triangle" is what is uploaded). SAH costs count a node visit as 4 triangle tests (vkpt's
default); `--leaf-size N` and `--traversal-cost C` change the tree for tuning runs.
Trees use object splits unless a row says otherwise (`--splits spatial|auto`): that is
the builder compared with Embree's; `vkpt` itself renders with `--splits auto`, which
builds both trees and keeps the one with the lower SAH cost (here: the object tree for
the procedural scene and the Cornell box, the spatial one for 2CylinderEngine).

Timings on this shared 2-core machine vary by up to 2× from run to run; compare the
tracers within one row (one run), not rows measured at different times.

HEAD
  echo "Measured $(date -u +%Y-%m-%d) on: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')."
  echo
  echo "| scene | threads | triangles | build Mtri/s | Embree build Mtri/s (1 thread) | SAH | CPU camera | CPU diffuse | GPU camera | GPU diffuse | Embree camera | Embree diffuse | CPU PT | GPU PT | mismatches |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
  cat <<'QUALITY'

## Time to quality

What users feel: seconds until the Cornell box at 256×256 reaches relMSE ≤ 1.2e-3 against
a converged reference (`bench/data/cornell-ref-16k.pfm`: CPU, 16,384 spp, seed 4242, made
with `build/vkpt --scene scenes/cornell.gltf --backend cpu --spp 16384 --width 256
--height 256 --seed 4242 --out bench/data/cornell-ref-16k.pfm`, ≈ 15 minutes). relMSE =
mean over pixels and channels of (a − r)² / (r² + 0.01); renders are progressive, timing
counts rendering only. For comparison, Blender 3.4 Cycles (CPU, 2 threads) needs 256 spp
and 12.8 s on this machine.

```
QUALITY
  echo "$quality"
  echo '```'
} > "$out"
echo "wrote $out"
