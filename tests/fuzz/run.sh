#!/usr/bin/env bash
# Runs the loader fuzzer for a fixed time; CI's fuzz smoke run (.ci/run) and longer
# local runs use it alike.
#   usage: tests/fuzz/run.sh [SECONDS=90] [BUILD_DIR=build-fuzz]
# Seeds: every .gltf/.glb of the glTF corpus (gltf-corpus/ of the external test data,
# $VKPT_TEST_DATA or ../shared, read in place), the PBR feature models under 4 MB
# (gltf-pbr/ there: textures, alpha, material
# extensions) and scenes/*.gltf; the corpus the run grows goes to a scratch directory
# outside the repository. Any finding (crash, sanitizer report, exception other than vkpt::Error,
# an input slower than 5 s, over 1 GiB in one allocation or 2 GiB resident) fails the
# run: the input is kept in the scratch directory, to be added to
# tests/fuzz/regressions/ (see the README there). Prints executions and coverage.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-90}
build=${2:-build-fuzz}
data=${VKPT_TEST_DATA:-../shared}
corpus=$data/gltf-corpus
pbr=$data/gltf-pbr
fuzzer="$build/fuzz_loader"
[ -x "$fuzzer" ] || { echo "fuzz: $fuzzer not built (README: Sanitizers and fuzzing)" >&2; exit 1; }
[ -d "$corpus/valid" ] && [ -d "$corpus/invalid" ] || { echo "fuzz: no glTF corpus at $corpus" >&2; exit 1; }

scratch=$(mktemp -d "${TMPDIR:-/tmp}/vkpt-fuzz-run-XXXXXX")
mkdir "$scratch/corpus" "$scratch/findings"
# libFuzzer takes single seed files as a comma-separated list.
{
  find "$corpus/valid" "$corpus/invalid" scenes -type f \( -name '*.gltf' -o -name '*.glb' \)
  if [ -d "$pbr" ]; then find "$pbr" -type f \( -name '*.gltf' -o -name '*.glb' \) -size -4M; fi
} | sort > "$scratch/seeds"
if grep -q , "$scratch/seeds"; then echo "fuzz: a seed path contains a comma" >&2; exit 1; fi
echo "fuzz: $(wc -l < "$scratch/seeds") seed files, ${seconds} s, scratch $scratch"
paste -sd, "$scratch/seeds" > "$scratch/seeds.csv"

status=0
"$fuzzer" "$scratch/corpus" -seed_inputs=@"$scratch/seeds.csv" -dict=tests/fuzz/gltf.dict \
  -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 -malloc_limit_mb=1024 \
  -artifact_prefix="$scratch/findings/" -print_final_stats=1 \
  < /dev/null > "$scratch/fuzz.log" 2>&1 || status=$?

execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$scratch/fuzz.log" | tail -1)
last=$(grep -E '^#[0-9]+.* cov: ' "$scratch/fuzz.log" | tail -1 || true)
cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<< "$last")
ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<< "$last")
corp=$(sed -n 's/.* corp: \([0-9]*\/[0-9a-zA-Z]*\).*/\1/p' <<< "$last")
rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$scratch/fuzz.log" | tail -1)
rss=$(sed -n 's/^stat::peak_rss_mb: *//p' "$scratch/fuzz.log" | tail -1)
echo "fuzz: executions ${execs:-?} (${rate:-?}/s), coverage cov ${cov:-?} ft ${ft:-?}, corpus ${corp:-?}, peak RSS ${rss:-?} MB"

if [ "$status" -ne 0 ] || [ -n "$(ls -A "$scratch/findings")" ]; then
  tail -n 60 "$scratch/fuzz.log" >&2
  echo "fuzz: FINDING (exit status $status); the input is kept:" >&2
  ls -l "$scratch/findings" >&2
  echo "fuzz: fix the loader, then copy the input to tests/fuzz/regressions/ (see its README.md)" >&2
  exit 1
fi
rm -rf "$scratch"
