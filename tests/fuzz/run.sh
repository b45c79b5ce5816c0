#!/usr/bin/env bash
# Runs the fuzz targets (tests/fuzz/CMakeLists.txt lists them) for a fixed time; CI's
# fuzz smoke run (.ci/run) and longer local runs use it alike.
#   usage: tests/fuzz/run.sh [SECONDS=90] [BUILD_DIR=build-fuzz]
#            every target, SECONDS split among them in equal shares (at least 1 s each)
#          tests/fuzz/run.sh --all SECONDS [BUILD_DIR=build-fuzz]
#            every target for SECONDS each
#          tests/fuzz/run.sh --only TARGET[,TARGET...] SECONDS [BUILD_DIR=build-fuzz]
#            the targets named (loader, env, texture, pfm, options, draco, meshopt),
#            SECONDS split among them in equal shares
# $VKPT_FUZZ_TIMEOUT (default 5) is the seconds an input may take: libFuzzer measures
# wall-clock time, so a long run on a machine busy with other work may raise it (a hang
# still ends the run; CI keeps 5).
# Seeds, read in place from the external test data ($VKPT_TEST_DATA or ../shared) and
# never copied into the repository:
#   loader   every .gltf/.glb of gltf-corpus/, the PBR feature models under 4 MB
#            (gltf-pbr/: textures, alpha, material extensions), the extension models
#            under 4 MB (gltf-ext/: clear coat, sheen, variants, skins...) and
#            scenes/*.gltf, and the kept findings of tests/fuzz/regressions/loader/
#   env      gltf-pbr/environments/*.hdr, and small .hdr/.exr files fuzz_seeds writes
#   texture  the PNG and JPEG files under 64 KB of gltf-pbr/ and gltf-corpus/, and small
#            ones fuzz_seeds writes in each pixel layout
#   pfm      small little- and big-endian PFM files fuzz_seeds writes
#   options  the command lines of tests/fuzz/options.seeds, NUL-separated
#   draco    Draco meshes fuzz_seeds encodes (sequential, edgebreaker, quantized), each
#            behind the small header of RunDraco (fuzz_bodies.h)
#   meshopt  meshoptimizer streams fuzz_seeds encodes (each mode and filter), each behind
#            the small header of RunMeshopt (fuzz_bodies.h)
# Generated seeds and the corpus each run grows go to a scratch directory outside the
# repository. Any finding (crash, sanitizer report, exception other than the target's
# documented error type, an input slower than $VKPT_FUZZ_TIMEOUT, over 1 GiB in one allocation or 2 GiB
# resident) fails the run once every target has run: the input is kept in the scratch
# directory, to be added to tests/fuzz/regressions/<target>/ (see the README there).
# Prints one line per target: "fuzz: <target>: executions N (R/s), coverage …".
set -euo pipefail
cd "$(dirname "$0")/../.."
targets=(loader env texture pfm options draco meshopt)
mode=split
case "${1:-}" in
  --all) mode=all; shift ;;
  --only) IFS=, read -ra targets <<< "${2:?--only needs a target}"; shift 2 ;;
esac
seconds=${1:-90}
build=${2:-build-fuzz}
data=${VKPT_TEST_DATA:-../shared}
corpus=$data/gltf-corpus
pbr=$data/gltf-pbr
ext=$data/gltf-ext
if [ "$mode" = split ]; then
  each=$((seconds / ${#targets[@]}))
  [ "$each" -ge 1 ] || each=1
else
  each=$seconds
fi
for t in "${targets[@]}" seeds; do
  [ -x "$build/fuzz_$t" ] || { echo "fuzz: $build/fuzz_$t not built (README: Sanitizers and fuzzing)" >&2; exit 1; }
done
[ -d "$corpus/valid" ] && [ -d "$corpus/invalid" ] || { echo "fuzz: no glTF corpus at $corpus" >&2; exit 1; }

# Leaks inside the libraries vkpt does not build, and only those, are not findings.
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
scratch=$(mktemp -d "${TMPDIR:-/tmp}/vkpt-fuzz-run-XXXXXX")
"$build/fuzz_seeds" "$scratch/generated"
mkdir "$scratch/generated/options"
n=0
while IFS= read -r line; do
  [ -n "$line" ] || continue
  n=$((n + 1))
  printf '%s' "$line" | tr ' ' '\0' > "$scratch/generated/options/$n"
done < tests/fuzz/options.seeds

# Seed files of one target, a path a line.
seeds_of() {
  case "$1" in
    loader)
      find "$corpus/valid" "$corpus/invalid" scenes -type f \( -name '*.gltf' -o -name '*.glb' \)
      if [ -d "$pbr" ]; then find "$pbr" -type f \( -name '*.gltf' -o -name '*.glb' \) -size -4M; fi
      if [ -d "$ext" ]; then find "$ext" -type f \( -name '*.gltf' -o -name '*.glb' \) -size -4M; fi
      # the kept findings too: one is a GLB with a Draco primitive, which no single-file
      # model of the shared data has (Duck's Draco variant needs its .bin)
      find tests/fuzz/regressions/loader -type f ;;
    env)
      if [ -d "$pbr/environments" ]; then find "$pbr/environments" -type f -name '*.hdr'; fi
      find "$scratch/generated/env" -type f ;;
    texture)
      find "$pbr" "$corpus" -type f \( -iname '*.png' -o -iname '*.jpg' -o -iname '*.jpeg' \) -size -64k 2> /dev/null || true
      find "$scratch/generated/texture" -type f ;;
    *) find "$scratch/generated/$1" -type f ;;
  esac
}

failed=()
for t in "${targets[@]}"; do
  dir=$scratch/$t
  mkdir "$dir" "$dir/corpus" "$dir/findings"
  seeds_of "$t" | sort > "$dir/seeds"
  if grep -q , "$dir/seeds"; then echo "fuzz: $t: a seed path contains a comma" >&2; exit 1; fi
  # libFuzzer takes single seed files as a comma-separated list.
  paste -sd, "$dir/seeds" > "$dir/seeds.csv"
  dict=()
  [ "$t" = loader ] && dict=(-dict=tests/fuzz/gltf.dict)
  echo "fuzz: $t: $(wc -l < "$dir/seeds") seed files, ${each} s, scratch $dir"
  status=0
  "$build/fuzz_$t" "$dir/corpus" -seed_inputs=@"$dir/seeds.csv" "${dict[@]}" \
    -max_total_time="$each" -timeout="${VKPT_FUZZ_TIMEOUT:-5}" -rss_limit_mb=2048 -malloc_limit_mb=1024 \
    -artifact_prefix="$dir/findings/" -print_final_stats=1 \
    < /dev/null > "$dir/fuzz.log" 2>&1 || status=$?

  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/fuzz.log" | tail -1)
  last=$(grep -E '^#[0-9]+.* cov: ' "$dir/fuzz.log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<< "$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<< "$last")
  corp=$(sed -n 's/.* corp: \([0-9]*\/[0-9a-zA-Z]*\).*/\1/p' <<< "$last")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$dir/fuzz.log" | tail -1)
  rss=$(sed -n 's/^stat::peak_rss_mb: *//p' "$dir/fuzz.log" | tail -1)
  echo "fuzz: $t: executions ${execs:-?} (${rate:-?}/s), coverage cov ${cov:-?} ft ${ft:-?}," \
       "corpus ${corp:-?}, peak RSS ${rss:-?} MB"

  if [ "$status" -ne 0 ] || [ -n "$(ls -A "$dir/findings")" ]; then
    tail -n 60 "$dir/fuzz.log" >&2
    # -timeout is wall-clock time: a loaded machine can make any input slow. Timed alone,
    # an input far within the limit was the machine's (regressions/README.md).
    for f in "$dir"/findings/timeout-*; do
      [ -e "$f" ] || continue
      start=$EPOCHREALTIME
      "$build/fuzz_$t" -runs=1 "$f" > /dev/null 2>&1 || true
      echo "fuzz: $t: $(basename "$f") replays alone in" \
           "$(awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.2f", b - a }') s" >&2
    done
    echo "fuzz: $t: FINDING (exit status $status); the input is kept:" >&2
    ls -l "$dir/findings" >&2
    failed+=("$t")
  fi
done

if [ "${#failed[@]}" -ne 0 ]; then
  echo "fuzz: findings from ${failed[*]}: fix the code, then copy each input to" \
       "tests/fuzz/regressions/<target>/ (see its README.md); scratch $scratch kept" >&2
  exit 1
fi
rm -rf "$scratch"
