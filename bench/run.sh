#!/usr/bin/env bash
# Regenerates bench/README.md from fresh measurements on this machine:
#   bash bench/run.sh            (after `cmake -B build && cmake --build build`)
set -euo pipefail
cd "$(dirname "$0")/.."
bench=build/vkpt-bench
corpus=${VKPT_TEST_DATA:-../shared}/gltf-corpus/valid
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
scaling="(not measured: build/vkpt was built without MPI, or mpirun is missing)"
if command -v mpirun > /dev/null && build/vkpt --version | grep -q 'rendering: MPI'; then
  scaling="$(bash bench/scaling.sh)"
fi
quality=""
if [ -f "$ref" ]; then
  quality="$($bench --scene scenes/cornell.gltf --quality "$ref" --threads 2 2>/dev/null)"
fi
many_lights="$($bench --scene scenes/many_lights.gltf --quality bench/data/many-lights-ref-8k.pfm --target 1e-2 \
  --threads 2 2>/dev/null)"
{
  cat <<'HEAD'
# Benchmarks

`build/vkpt-bench` traces the same rays with every tracer vkpt has — the CPU reference's
ordered stack traversal of eight-wide nodes, the GLSL walk of four-wide nodes (trace.comp) on
the Vulkan device — and with Intel Embree 3 (`rtcIntersect1` through its HIGH-quality
tree) when it was found at configure time; it cross-checks their closest hits and reports
full path-tracing rates.

```sh
build/vkpt-bench --procedural 1000000 --threads 1          # human-readable, with % of Embree
build/vkpt-bench --scene scenes/cornell.gltf --json         # one JSON object
bash bench/run.sh                                           # regenerates this file
```

Rays: 1024×1024 camera rays through pixel centres, then one cosine-weighted bounce from
every hit ("diffuse"). Mrays/s, each the fastest of three runs over the set; path tracing in Msamples/s at 256×256 × 16 spp, max depth
32. `--threads` applies to every tracer (CPU threads, Embree's thread count, and
`LP_NUM_THREADS` for lavapipe). "mismatches": rays whose hit distance differs between
tracers by more than 1e-4 relative (grazing hits on shared edges). Build rates are the
best of three builds, vkpt's with `--threads` threads and Embree's (BUILD_QUALITY_MEDIUM,
its binned SAH) with one; `--json` also gives vkpt's one-thread rate from the same run
(`build_mtris_per_s_1t`) and the run's peak host memory (`peak_rss_mib`: scene, trees,
ray sets, lavapipe and Embree together; "GPU bytes per triangle" is what is uploaded). SAH costs count a node visit as 4 triangle tests (vkpt's
default); `--leaf-size N` and `--traversal-cost C` change the tree for tuning runs.
Trees use object splits unless a row says otherwise (`--splits spatial|auto`): that is
the builder compared with Embree's MEDIUM one; Embree traces every row through its HIGH
tree (spatial splits), so the "spatial splits" rows compare the walks like for like; `vkpt` itself renders with `--splits auto`, which
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
and 12.8 s on this machine. Each backend runs with both light samplers (`--light-sampler
power` and `tree`; `vkpt` itself keeps `power` for the box's two emissive triangles),
the tree's time also given as a ratio to the power choice's in the same run.

```
QUALITY
  echo "$quality"
  echo '```'
  cat <<'MANY'

### Many lights

`scenes/many_lights.gltf`: a 40 m hall with 14 pillars lit by 1,000 small emissive quads
(6–20 cm) of eight powers from 2 to 256, at 128×96 until relMSE ≤ 1e-2 against
`bench/data/many-lights-ref-8k.pfm` (CPU, 8,192 spp with the light tree, seed 4242,
estimated relMSE 1.9e-4; `build/vkpt --scene scenes/many_lights.gltf --backend cpu
--light-sampler tree --spp 8192 --width 128 --height 96 --seed 4242 --out
bench/data/many-lights-ref-8k.pfm`, ≈ 8 minutes).
"relMSE at equal time" multiplies the mean relMSE of 8 independent renders of 32 spp by
their mean time, for each light sampler: an unbiased render's expected relMSE falls as
1/time, so the ratio of the products is that of relMSE at equal time. The first crossing
of a threshold (the times above) comes early for the noisier estimator, which makes it
the weaker measure of the two; the ± is the standard error from the renders' relMSE
spread, not from the machine's timing drift (run to run, ±10 %).

```
MANY
  echo "$many_lights"
  echo '```'
  cat <<'SCALING'

## Distributed rendering

One frame over MPI ranks on this machine (`bench/scaling.sh`): the Cornell box at 256² ×
256 spp in 16 chunks of 16 spp, one thread per rank (`--threads 1`, `mpirun --bind-to
none --oversubscribe`). "render s" is `times_s.render`: from the first chunk dealt to the
last one added, on rank 0's clock (each rank's scene load and BVH build come before, in
parallel). With 2 cores, 4 ranks are oversubscribed: they share the cores and cannot be
faster than 2. "image": the file compared byte for byte with the one-process render.

SCALING
  echo "$scaling"
  cat <<'MODEL'

A rank sends a 48-byte header and 52 bytes per pixel per chunk (Σf, Σf² as doubles and
the count), or 28 when every sum is a float exactly, as a GPU's are: for a CPU rank 3.4 MB
per 256² chunk, 13.6 MB at 512², 108 MB at 1920 × 1080; a GPU rank about half that. Rank 0 adds each chunk to the frame as it
arrives, while its own thread renders.
A model of k machines, each rendering a chunk in t seconds, with C chunks of B bytes and
rank 0 receiving at b bytes/s:

    T(k) ≈ load + ⌈C / k⌉ · t + B / b        (the last chunk's transfer is not hidden)
    speed-up ≈ C·t / (⌈C / k⌉ · t + B / b),  until rank 0's link saturates at k ≈ t·b / B

With this machine's figures (t = 0.70 s per 256² chunk on one CPU core, B = 3.4 MB) and
1 Gbit/s Ethernet (b ≈ 117 MB/s, B / b = 29 ms), k = 2, 4, 8, 16 machines would give
1.99×, 3.96×, 7.8× and 15.4× (load left out), and rank 0's link would saturate near
k = 24. On this machine 2 ranks measured 1.72–1.88× (over several runs) against the model's 1.99×: rank 0's
dealing and adding, and whatever else runs, share its 2 cores. The chunk count
caps the speed-up at C: a render meant for many machines needs spp / `--chunk` of at
least the number of ranks (`--chunk` is part of the image, like the seed: choose it once).

## Big scenes

Measured 2026-12-02 (by hand; not regenerated by this script): the procedural scene at
10 M triangles, `build/vkpt-bench --procedural 10000000 --threads 2`, and the same scene
as a 343 MiB GLB (`--write-glb`, 3.2 s, 1.1 GiB peak) rendered by `build/vkpt` at 256² ×
16 spp with the default `--splits auto` (both trees built, the object one kept):

| run | peak host memory | BVH build | GPU bytes per triangle | samples/s |
|---|---|---|---|---|
| vkpt-bench, 9,994,358 triangles | 4.27 GiB (with Embree's tree) | 2.08 s (object splits, 2 threads; 4.8 Mtri/s) | 59.4 | CPU 0.572 M, lavapipe 0.243 M |
| vkpt, CPU | 3.90 GiB | 13.6 s (both trees), load 2.8 s | — | 0.340 M |
| vkpt, lavapipe | 3.95 GiB | 9.6 s (both trees, the GPU's 8 copies), load 2.9 s, upload 1.8 s | 59.4 | 0.266 M |

A tree this large keeps one copy (the eight direction-ordered copies only below 128 MiB),
so the GPU holds 48 bytes per triangle and 32 per node.

**Past one texel buffer** (2026-12-03, by hand): `--procedural 46500000 --write-glb` (a
1.6 GiB GLB, written in 24 s at 5.1 GiB peak) has 46,484,614 triangle references, 139.5 M
texels against lavapipe's `maxTexelBufferElements` of 2^27 = 134.2 M, so its triangles
take two texel buffers. `build/vkpt --splits object --max-memory 40G` at 256²:

| run | peak host memory | load | BVH build | upload | samples/s |
|---|---|---|---|---|---|
| lavapipe, 4 spp | 9.07 GiB | 34.9 s | 9.2 s (16.7 M nodes) | 7.8 s | 0.191 M |
| `--compare`, 16 spp | 11.6 GiB | — | 11.9 s | — | CPU 0.305 M, lavapipe 0.140 M |

The two images agree: 0.22 % of channels beyond 1e-3 in lockstep (the limit is 1 %) and
none of 768 region tests significant. `--max-memory` had to be raised: the loader counts
560 bytes per triangle before reading (both trees of `--splits auto`, with normals), 32 GiB
here, while the peak was 196 bytes per triangle; with the default budget of half the RAM a
24 GiB machine refuses scenes above about 17 M triangles, naming `--max-memory`. On
lavapipe the triangles and texture coordinates stop at two buffers, 89.4 M triangles; the
next one-buffer limits are 2^27 texels for the BVH nodes (67 M nodes, about 190 M
triangles of this scene) and for vertex colours (2 texels per triangle: 67 M). These runs
predate the GPU's four-wide nodes (below): its nodes are now 64 bytes, about four times
fewer (2CylinderEngine: about 10,000 per copy against 41,685 flattened ones; leaves are
slots of their parents), and their limit is 33 M.

## The GPU's four-wide walk against the binary one

2026-12-06 (by hand; not regenerated by this script): `build/vkpt-bench --threads 1`
with `LP_NUM_THREADS=1`, the binary skip-link walk (e17bca3) and the four-wide quantised
walk alternating in one session, medians of 2–3 runs (Mrays/s; path tracing Msamples/s;
each run's figures in docs/design-notes.md, "GPU: wide nodes"). Node texels per camera
ray from the heat map AOV at 256², 1 spp (`--splits auto`):

| scene | rays | binary | four-wide | wide / binary |
|---|---|---|---|---|
| procedural 1 M triangles | camera | 5.28 | 6.03 | 1.14 |
| procedural 1 M triangles | diffuse | 1.30 | 1.92 | 1.48 |
| procedural 1 M triangles | path tracing | 0.177 | 0.268 | 1.52 |
| 2CylinderEngine | camera | 5.00 | 4.56 | 0.91 |
| 2CylinderEngine | diffuse | 2.68 | 2.81 | 1.05 |
| 2CylinderEngine | path tracing | 0.827 | 0.844 | 1.02 |
| DamagedHelmet | camera | 11.2 | 10.2 | 0.91 |
| DamagedHelmet | diffuse | 2.86 | 3.60 | 1.26 |
| DamagedHelmet | path tracing | 1.45 | 1.65 | 1.13 |
| Cornell box | diffuse | 7.46 | 8.08 | 1.08 |
| Cornell box | path tracing | 0.891 | 0.965 | 1.08 |
| 2CylinderEngine | node texels per camera ray | 44.6 | 31.0 | 0.70 |
| DamagedHelmet | node texels per camera ray | 19.1 | 13.2 | 0.69 |
| Cornell box | node texels per camera ray | 15.1 | 6.3 | 0.42 |

GPU bytes per triangle (triangles and every node copy): 144.7 → 94.5 on 2CylinderEngine,
140.8 → 95.3 on the procedural scene. Against Embree in the same runs the GPU's diffuse
rays went from 35 % to 51 % of Embree's rate on the procedural scene (camera rays 63 % to
68–71 %), and stayed at 33–34 % on 2CylinderEngine (camera rays 45 % to 41 %).

## What the material extensions cost scenes without them

Samples/s of `vkpt` before clear coat, sheen and diffuse transmission (33ee8ec) and after
(3c775dc), three alternating runs each in one session, 2 cores, lavapipe with
`LP_NUM_THREADS=2` (`--stats` `samples_per_s`; Cornell box 160², 128 spp; MetalRoughSpheres
under potsdamer_platz_1k.hdr 160², 64 spp). Both images are bit-identical before and after.

| scene | backend | before (M samples/s) | after | after / before |
|---|---|---|---|---|
| Cornell box | CPU | 2.25 | 2.40 | 1.07 |
| MetalRoughSpheres | CPU | 2.05 | 2.00 | 0.97 |
| Cornell box | lavapipe | 1.36 | 1.36 | 1.00 |
| MetalRoughSpheres | lavapipe | 1.08 | 1.07 | 0.99 |

One binary's runs spread by up to ±12 % on this machine: no cost is measurable. The extensions cost
the material table 32 bytes per material (8 texels instead of 6) and nothing else where
no material uses them (specialization constants 13–15 on the GPU, the simple estimator
on the CPU).

Iridescence and anisotropy (15d5c34 against e18a4a1 and its out-of-line rare paths),
measured the same way and then one thread at a time, best of six alternating runs
(MetalRoughSpheres 128², 64 spp, `--splits object`), since two-thread runs spread by
±12 %:

| scene | backend | before | after | after / before |
|---|---|---|---|---|
| Cornell box | CPU, CPU seconds for 160² × 256 spp (median of 5) | 6.02 s | 6.07 s | 1.01 |
| MetalRoughSpheres | CPU, 1 thread, best of 6 (M samples/s) | 1.045 | 0.920 | 0.88 |
| Cornell box | lavapipe, median of 4 (M samples/s) | 1.31 | 1.35 | 1.03 |
| MetalRoughSpheres | lavapipe, median of 3 | 1.14 | 1.11 | 0.97 |

The images are bit-identical. On lavapipe the specialization constants 16 and 17 drop the
film and the anisotropic lobe, and their material texels are not fetched: no cost is
measurable. The CPU's glossy estimator decided per material at run time, and its timings
above differ by up to 12 %, within what one binary's runs spread. Instructions do not
spread: counted by callgrind over the render alone (`valgrind --tool=callgrind
--toggle-collect='*RunThreads*'`, MetalRoughSpheres under potsdamer_platz_1k.hdr, 48²,
16 spp, one thread, `--splits object`; the images bit-identical):

| CPU estimator | instructions (M) | / before |
|---|---|---|
| before iridescence and anisotropy (15d5c34) | 127.89 | 1.000 |
| general, with them and dispersion (ddaac2f) | 130.56 | 1.021 |
| general, all six layered extensions compiled out (a test build) | 125.67 | 0.983 |
| `core_path.cpp`: the estimator without them, chosen for scenes that use none | 127.03 | 0.993 |

So the CPU now picks, as lavapipe does, an estimator compiled for what the scene uses:
the simple one (Lambert-only scenes), the core one (no clear coat, sheen, diffuse
transmission, iridescence, anisotropy or dispersion on any triangle), or the general one.
The core one runs the general one's bits (`Render.CoreSceneEstimatorEqualsTheGeneralOne`)
and costs 0.7 % fewer instructions than before the film and the anisotropic lobe.
Dispersion (ddaac2f) adds a specialization constant on the GPU and one branch per hit on
the general CPU estimator; the Cornell box and DamagedHelmet render bit-identically.

## What position-independent code costs

Since libvkpt.so and the Python module link the same layers as the `vkpt` executable,
everything is compiled with `-fPIC`, hidden visibility and `-fno-semantic-interposition`
(CMakeLists.txt). Measured in one run, the two builds' executables alternating three times
(CPU backend, 2 threads, 256 × 256, wall seconds with load): Cornell box at 256 spp 7.98 s
(median; 7.94–8.15) before and 8.13 s (7.87–8.25) after, ratio 1.02 with the ranges
overlapping; DamagedHelmet at 32 spp 1.07 s (1.04–1.25) and 1.12 s (1.06–1.16). The images
are bit-identical (Cornell c5762c21, DamagedHelmet b34cf897 on the CPU; dc58ee5f and
b5941bf5 on lavapipe).
## Soak

Measured 2026-12-07 (by hand; not regenerated by this script): `bash bench/soak.sh` (one
render of `--time 600` at 64², 10,000 Python renders of one `vkpt.Scene` at 32² × 1 spp,
a `--frames` sequence of 10,000 frames at 16² × 1 spp), lavapipe, 2 cores, against the
build before the frame constants left lavapipe's uniform buffers (9aca402, a shorter run:
`VKPT_BUILD=... bash bench/soak.sh 120 2000 2000`, stopped after 261 s).
Resident memory (MiB) at points of each run; docs/design-notes.md, "Frame constants in a
storage buffer", has the cause:

| run | point | before | after |
|---|---|---|---|
| one render, 64² | 12 s | 637 | 447 |
| | 60 s | 1,434 | 447 |
| | 120 s | 2,408 (peak 2,431) | 447 |
| | 600 s | — | 447 (219,081 spp, 609 passes; peak 447) |
| Python renders, 32² | render 200 | 619 (heap in use 195) | 456 (heap 18.1) |
| | render 2,000 | 2,051 (heap 1,792) | 456 (heap 18.1) |
| | render 10,000 | — | 456 (heap 18.1), in 15 s |
| `--frames`, 16² | frame 337 | 811 | 447 |
| | frame 1,834 | 2,252, at 261 s | 447 |
| | frame 10,000 | — | 447 (peak 446), in 22 s |

Before, each render kept 0.9 MB of heap and each frame about 1 MB, and a long render grew
16 MB a second; after, the peak of every run is its first pass's (the kernel's compile).
lavapipe's resident memory hides a smaller growth under what its compile left: a sequence
also kept each frame's stats, 1.9 kB, with or without `--stats` (on the CPU backend 10,000
frames at 8² peaked at 27.3 MB against 9.2 MB for 100); it keeps them only for `--stats`
now, and then 9.2 MB for 10,000 frames without.
The lavapipe re-optimisation at each bind also cost time: 2,000 Python renders took 16 s
before and 3 s after, a 16² frame 142 ms before and 2.2 ms after (PNG written included).
MODEL
} > "$out"
echo "wrote $out"
